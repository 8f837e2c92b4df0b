// The scalp (scalp.h) on a hand-made head: a sphere 10 cm in radius, with sheets of hair
// lying on it and standing off it, behind it and in front of it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "hair/extract/scalp.h"
#include "unit/icosphere.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 0.1;
const Vec3 kCentre(0, 1.5, 0);
constexpr double kNeckY = 1.5;                             // the sphere's upper half is the head
constexpr double kMaxDistance = 0.015;                     // scalp_distance_h's metres
constexpr double kUnderHair = 0.035;                       // scalp_under_hair_h's metres
constexpr double kPolarFirstDeg = 40, kPolarLastDeg = 80;  // a sheet's extent down the head
constexpr double kHalfWidthDeg = 25;                       // ...and across it, in azimuth

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

/// The sphere's scalp settings: hair within kMaxDistance, under hair to `under_hair_m`
/// from `min_height_m` above the neck, no face.
ScalpParams scalp_params(double under_hair_m, double min_height_m) {
  ScalpParams params;
  params.neck_y = kNeckY;
  params.max_distance_m = kMaxDistance;
  params.under_hair_m = under_hair_m;
  params.under_hair_min_height_m = min_height_m;
  return params;
}

/// Direction from the centre at polar angle `polar_deg` (from +Y) and azimuth `azimuth_deg`
/// (from +Z, the face, towards +X).
Vec3 direction(double polar_deg, double azimuth_deg) {
  const double p = radians(polar_deg), a = radians(azimuth_deg);
  return {std::sin(p) * std::sin(a), std::cos(p), std::sin(p) * std::cos(a)};
}

/// A sheet of quads `height_m` off the sphere, centred on azimuth `azimuth_deg`.
void add_sheet(PolyMesh& mesh, double azimuth_deg, double height_m) {
  constexpr int kRows = 9, kColumns = 11;
  const auto first = static_cast<int32_t>(mesh.vertices.rows());
  Points3f vertices(mesh.vertices.rows() + kRows * kColumns, 3);
  vertices.topRows(mesh.vertices.rows()) = mesh.vertices;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kColumns; ++j) {
      const double polar = kPolarFirstDeg + (kPolarLastDeg - kPolarFirstDeg) * i / (kRows - 1);
      const double azimuth = azimuth_deg - kHalfWidthDeg + 2 * kHalfWidthDeg * j / (kColumns - 1);
      vertices.row(mesh.vertices.rows() + i * kColumns + j) =
          (kCentre + (kRadius + height_m) * direction(polar, azimuth)).cast<float>().transpose();
    }
  mesh.vertices = vertices;
  for (int i = 0; i + 1 < kRows; ++i)
    for (int j = 0; j + 1 < kColumns; ++j) {
      const int32_t a = first + i * kColumns + j;
      const std::vector<int32_t> quad = {a, a + kColumns, a + kColumns + 1, a + 1};
      mesh.append_face(quad);
    }
}

/// Where body triangle `t`'s centroid lies on the sphere: azimuth (from +Z, the face,
/// towards +X) and polar angle (from +Y), degrees; height above the neck, metres.
struct TrianglePlace {
  double azimuth_deg = 0, polar_deg = 0, height_m = 0;
};
TrianglePlace place_of(const testing::SphereMesh& body, Eigen::Index t) {
  Vec3 centroid = Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    centroid += body.vertices.row(body.triangles(t, k)).cast<double>().transpose() / 3;
  const Vec3 from_centre = (centroid - kCentre).normalized();
  return {std::atan2(from_centre.x(), from_centre.z()) * 180 / std::numbers::pi,
          std::acos(from_centre.y()) * 180 / std::numbers::pi, centroid.y() - kNeckY};
}

/// Of the body triangles under the middle of the sheet at `azimuth_deg` (centroid within
/// 10 degrees of its middle across, 45-75 degrees down), the share marked.
double marked_share_under(const testing::SphereMesh& body, const std::vector<uint8_t>& scalp,
                          double azimuth_deg) {
  int64_t under = 0, marked = 0;
  const Vec3 middle = direction(60, azimuth_deg);
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    Vec3 centroid = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      centroid += body.vertices.row(body.triangles(t, k)).cast<double>().transpose() / 3;
    const Vec3 from_centre = (centroid - kCentre).normalized();
    const double polar_deg = std::acos(from_centre.y()) * 180 / std::numbers::pi;
    const Vec3 across = from_centre - from_centre.dot(middle) * middle;
    if (polar_deg < 45 || polar_deg > 75 || from_centre.dot(middle) < std::cos(radians(20)) ||
        across.norm() > std::sin(radians(10)))
      continue;
    ++under;
    marked += scalp[static_cast<size_t>(t)];
  }
  EXPECT_GT(under, 5);
  return under > 0 ? static_cast<double>(marked) / static_cast<double>(under) : 0;
}

// Hair lying on the head (5 mm off, at the side, azimuth 90) marks the scalp under it by
// distance; hair standing 3 cm off behind the head (azimuth 180, a bob's shell) marks the
// scalp under it only with scalp_under_hair; the same in front of the face (azimuth 0)
// never: hair hanging there is rooted above it.
TEST(Scalp, HairStandingOffTheHeadMarksTheScalpUnderItButNotTheFace) {
  const testing::SphereMesh body = testing::icosphere(4, kRadius, kCentre);
  PolyMesh hair;
  add_sheet(hair, 90, 0.005);
  add_sheet(hair, 180, 0.03);
  add_sheet(hair, 0, 0.03);
  const std::vector<uint8_t> with_under =
      scalp_triangles(body.vertices, body.triangles, hair, scalp_params(kUnderHair, 0));
  const std::vector<uint8_t> by_distance =
      scalp_triangles(body.vertices, body.triangles, hair, scalp_params(0, 0));
  EXPECT_EQ(marked_share_under(body, with_under, 90), 1.0);
  EXPECT_EQ(marked_share_under(body, by_distance, 90), 1.0);
  EXPECT_EQ(marked_share_under(body, with_under, 180), 1.0);
  EXPECT_EQ(marked_share_under(body, by_distance, 180), 0.0);
  EXPECT_EQ(marked_share_under(body, with_under, 0), 0.0);
  EXPECT_EQ(marked_share_under(body, by_distance, 0), 0.0);
  // Nothing below the neck.
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    double centroid_y = 0;
    for (int k = 0; k < 3; ++k) centroid_y += body.vertices(body.triangles(t, k), 1) / 3.0;
    if (centroid_y < kNeckY) {
      EXPECT_EQ(with_under[static_cast<size_t>(t)], 0);
    }
  }
  // A shell farther off than scalp_under_hair reaches marks nothing under it.
  PolyMesh far;
  add_sheet(far, 180, 0.06);
  EXPECT_EQ(
      marked_share_under(
          body, scalp_triangles(body.vertices, body.triangles, far, scalp_params(kUnderHair, 0)),
          180),
      0.0);
}

// Hair standing off the lowest part of the head hangs past it from above (a ponytail's tail
// behind the nape): with scalp_under_hair_min_height, the shell behind the head marks the
// scalp under it only that far above the neck; by distance, hair lying on the head marks it
// down to the neck as before.
TEST(Scalp, HairStandingOffTheHeadMarksNoScalpNearTheNeck) {
  const testing::SphereMesh body = testing::icosphere(4, kRadius, kCentre);
  PolyMesh hair;
  add_sheet(hair, 90, 0.005);
  add_sheet(hair, 180, 0.03);
  constexpr double kMinHeight = 0.04;
  const std::vector<uint8_t> scalp =
      scalp_triangles(body.vertices, body.triangles, hair, scalp_params(kUnderHair, kMinHeight));
  int64_t low_behind = 0, high_behind = 0, low_side = 0;
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    const TrianglePlace place = place_of(body, t);
    if (place.polar_deg < kPolarFirstDeg + 5 || place.polar_deg > kPolarLastDeg - 5) continue;
    const double azimuth_deg = place.azimuth_deg, height_m = place.height_m;
    const auto marked = scalp[static_cast<size_t>(t)];
    if (std::abs(std::abs(azimuth_deg) - 180) < 15) {
      if (height_m < kMinHeight) {
        ++low_behind;
        EXPECT_EQ(marked, 0) << "behind the head at " << height_m << " m above the neck";
      } else if (height_m > kMinHeight + 0.005) {
        ++high_behind;
        EXPECT_EQ(marked, 1) << "behind the head at " << height_m << " m above the neck";
      }
    } else if (std::abs(azimuth_deg - 90) < 15 && height_m < kMinHeight) {
      ++low_side;
      EXPECT_EQ(marked, 1) << "under hair lying on the head at " << height_m << " m";
    }
  }
  EXPECT_GT(low_behind, 5);
  EXPECT_GT(high_behind, 5);
  EXPECT_GT(low_side, 5);
}

// A fringe lying on the face (5 mm off, in front, azimuth 0) marks the scalp under it by
// distance only above the brows (face_below_y): below, the face is never scalp. Hair lying
// on the side of the head (azimuth 90) marks it down to the neck: the body there faces
// sideways. Without face_below_y the fringe marks the face too.
TEST(Scalp, AFringeOverTheFaceMarksNoScalpBelowTheBrows) {
  const testing::SphereMesh body = testing::icosphere(4, kRadius, kCentre);
  PolyMesh hair;
  add_sheet(hair, 0, 0.005);
  add_sheet(hair, 90, 0.005);
  constexpr double kBrowAboveNeck = 0.05;  // polar angle 60 degrees
  ScalpParams params = scalp_params(0, 0);
  params.face_below_y = kNeckY + kBrowAboveNeck;
  params.face_radius_m = 0.02;
  const std::vector<uint8_t> scalp = scalp_triangles(body.vertices, body.triangles, hair, params);
  const std::vector<uint8_t> without_face =
      scalp_triangles(body.vertices, body.triangles, hair, scalp_params(0, 0));
  int64_t face = 0, brow = 0, side = 0;
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    const TrianglePlace place = place_of(body, t);
    if (place.polar_deg < kPolarFirstDeg + 5 || place.polar_deg > kPolarLastDeg - 5) continue;
    const double azimuth_deg = place.azimuth_deg, height_m = place.height_m;
    const auto t_index = static_cast<size_t>(t);
    if (std::abs(azimuth_deg) < 15) {
      if (height_m < kBrowAboveNeck) {
        ++face;
        EXPECT_EQ(scalp[t_index], 0) << "face at " << height_m << " m above the neck";
        EXPECT_EQ(without_face[t_index], 1);
      } else {
        ++brow;
        EXPECT_EQ(scalp[t_index], 1) << "above the brows at " << height_m << " m";
      }
    } else if (std::abs(azimuth_deg - 90) < 15) {
      ++side;
      EXPECT_EQ(scalp[t_index], 1) << "side of the head at " << height_m << " m";
    }
  }
  EXPECT_GT(face, 5);
  EXPECT_GT(brow, 5);
  EXPECT_GT(side, 5);
}

// An ear: a slab 6 mm thick, 3 cm tall and 2 cm wide standing out from the side of the
// head (azimuth 90, its inner edge 0.5 mm off the sphere), as a closed box. Hair lying on
// the side of the head over it (a sheet 5 mm off the sphere, reaching round the slab)
// marks the sphere under it as scalp, but not the slab: the body behind the slab's faces
// is thinner than ear_thickness_m along their inward normal.
TEST(Scalp, AnEarUnderHairIsNotScalp) {
  testing::SphereMesh body = testing::icosphere(4, kRadius, kCentre);
  const Vec3 side = direction(60, 90);  // the ear's middle, out from the centre
  const Vec3 up = (Vec3::UnitY() - Vec3::UnitY().dot(side) * side).normalized();
  const Vec3 across = side.cross(up);
  // Corners: out in [0.5 mm, 20 mm] from the surface along `side`, +-15 mm along `up`,
  // +-3 mm along `across`.
  const testing::SphereMesh head = body;
  std::vector<Vec3> corner;
  for (double out : {0.0005, 0.02})
    for (double along_up : {-0.015, 0.015})
      for (double along_across : {-0.003, 0.003})
        corner.push_back(kCentre + (kRadius + out) * side + along_up * up + along_across * across);
  const auto first = static_cast<int32_t>(body.vertices.rows());
  body.vertices.conservativeResize(first + 8, 3);
  for (int k = 0; k < 8; ++k)
    body.vertices.row(first + k) = corner[static_cast<size_t>(k)].cast<float>().transpose();
  // Box faces (index = out * 4 + up * 2 + across), wound outward.
  const std::vector<std::array<int, 4>> quads = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                                 {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  const auto before = body.triangles.rows();
  body.triangles.conservativeResize(before + 12, 3);
  for (size_t q = 0; q < quads.size(); ++q) {
    const auto& v = quads[q];
    body.triangles.row(before + 2 * static_cast<Eigen::Index>(q)) << first + v[0], first + v[1],
        first + v[2];
    body.triangles.row(before + 2 * static_cast<Eigen::Index>(q) + 1) << first + v[0], first + v[2],
        first + v[3];
  }
  PolyMesh hair;
  add_sheet(hair, 90, 0.005);
  add_sheet(hair, 90, 0.021);  // over the ear's outer edge
  ScalpParams params = scalp_params(0, 0);
  params.ear_thickness_m = 0.012;
  const std::vector<uint8_t> thin =
      thin_triangles(body.vertices, body.triangles, kNeckY, params.ear_thickness_m);
  const std::vector<uint8_t> scalp = scalp_triangles(body.vertices, body.triangles, hair, params);
  const std::vector<uint8_t> with_ear =
      scalp_triangles(body.vertices, body.triangles, hair, scalp_params(0, 0));
  // The slab's two broad faces (the +-across sides, triangles 4-7 of its 12) are thin; the
  // sphere is not.
  for (Eigen::Index t = before; t < before + 12; ++t) {
    const Eigen::Index face = (t - before) / 2;
    if (face == 4 || face == 5) {
      EXPECT_EQ(thin[static_cast<size_t>(t)], 1) << "ear triangle " << t - before;
      EXPECT_EQ(scalp[static_cast<size_t>(t)], 0) << "ear triangle " << t - before;
      EXPECT_EQ(with_ear[static_cast<size_t>(t)], 1) << "ear triangle " << t - before;
    }
  }
  int64_t head_thin = 0;
  for (Eigen::Index t = 0; t < before; ++t) head_thin += thin[static_cast<size_t>(t)];
  EXPECT_EQ(head_thin, 0);
  EXPECT_EQ(
      marked_share_under(head, std::vector<uint8_t>(scalp.begin(), scalp.begin() + before), 90),
      1.0);
}

}  // namespace
}  // namespace hair
