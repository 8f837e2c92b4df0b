// The scalp (scalp.h) on a hand-made head: a sphere 10 cm in radius, with sheets of hair
// lying on it and standing off it, behind it and in front of it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
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
      scalp_triangles(body.vertices, body.triangles, kNeckY, hair, kMaxDistance, kUnderHair);
  const std::vector<uint8_t> by_distance =
      scalp_triangles(body.vertices, body.triangles, kNeckY, hair, kMaxDistance, 0);
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
  EXPECT_EQ(marked_share_under(body,
                               scalp_triangles(body.vertices, body.triangles, kNeckY, far,
                                               kMaxDistance, kUnderHair),
                               180),
            0.0);
}

}  // namespace
}  // namespace hair
