#include "hair/grow/followed_card_flow.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "hair/core/error.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr int8_t kAlongInputStrand = 2;  // GrowRule::input_strand (grow/strand_growing.h)

/// The triangles of some faces of a mesh, with the face of each, and their distance.
struct FaceTriangles {
  std::vector<int64_t> face;  ///< per triangle
  std::unique_ptr<TriangleMeshDistance> distance;
};

/// Of the mesh's fan triangles `triangles` (faces `triangle_face`), those of the faces in
/// `group` (every one when it is negative).
FaceTriangles face_triangles(const PolyMesh& mesh, const Triangles3i& triangles,
                             const std::vector<int64_t>& triangle_face,
                             const std::vector<int32_t>& face_group, int32_t group) {
  FaceTriangles out;
  std::vector<Eigen::Index> rows;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const int64_t face = triangle_face[static_cast<size_t>(t)];
    if (group >= 0 && face_group[static_cast<size_t>(face)] != group) continue;
    rows.push_back(t);
    out.face.push_back(face);
  }
  if (rows.empty()) return out;
  Triangles3i kept(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i)
    kept.row(static_cast<Eigen::Index>(i)) = triangles.row(rows[i]);
  out.distance = std::make_unique<TriangleMeshDistance>(mesh.vertices, kept);
  return out;
}

}  // namespace

double followed_card_flow_agreement(const PolyMesh& mesh, const std::vector<int32_t>& face_group,
                                    const PaintedFlow& flow, const StrandSet& grown,
                                    const std::vector<int32_t>& point_group,
                                    const std::vector<int8_t>& point_rule, double min_coherence,
                                    double max_angle_deg, double max_distance_m, int64_t& counted) {
  const auto faces = static_cast<size_t>(mesh.face_count());
  const auto points = static_cast<size_t>(grown.point_count());
  if (face_group.size() != faces || flow.coherence.size() != faces ||
      flow.direction.size() != faces)
    throw Error::bad_input("followed card flow", "per-face groups or flow do not match the mesh");
  if (point_group.size() != points || point_rule.size() != points)
    throw Error::bad_input("followed card flow",
                           "per-point groups or rules do not match the strands");
  counted = 0;
  const Triangles3i triangles = fan_triangulation(mesh.face_offsets, mesh.face_vertices);
  std::vector<int64_t> triangle_face;  // fan_triangulation's order: face by face
  for (int64_t face = 0; face < mesh.face_count(); ++face)
    triangle_face.insert(triangle_face.end(),
                         static_cast<size_t>(std::max(0, mesh.face_size(face) - 2)), face);
  const FaceTriangles all = face_triangles(mesh, triangles, triangle_face, face_group, -1);
  if (!all.distance) return 0;
  // Per followed group, its own faces (a group without faces: judged against them all).
  std::map<int32_t, FaceTriangles> own;
  for (size_t row = 0; row < points; ++row)
    if (point_rule[row] == kAlongInputStrand && point_group[row] >= 0 &&
        !own.count(point_group[row]))
      own.emplace(point_group[row],
                  face_triangles(mesh, triangles, triangle_face, face_group, point_group[row]));
  const double min_cosine = std::cos(max_angle_deg * std::numbers::pi / 180);
  int64_t agreeing = 0, judged = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : agreeing, judged)
  for (int64_t s = 0; s < grown.strand_count(); ++s)
    for (int64_t row = grown.offsets[static_cast<size_t>(s)] + 1;
         row < grown.offsets[static_cast<size_t>(s) + 1]; ++row) {
      const Vec3 a = grown.points.row(row - 1).cast<double>().transpose();
      const Vec3 b = grown.points.row(row).cast<double>().transpose();
      if (!((b - a).norm() > 1e-9)) continue;
      const FaceTriangles* searched = &all;
      if (point_rule[static_cast<size_t>(row)] == kAlongInputStrand) {
        const auto found = own.find(point_group[static_cast<size_t>(row)]);
        if (found != own.end() && found->second.distance) searched = &found->second;
      }
      const TriangleMeshDistance::Nearest nearest = searched->distance->nearest(0.5 * (a + b));
      if (nearest.triangle < 0 || nearest.distance > max_distance_m) continue;
      const auto face = static_cast<size_t>(searched->face[static_cast<size_t>(nearest.triangle)]);
      if (!(flow.coherence[face] >= min_coherence)) continue;
      ++judged;
      if (std::abs((b - a).normalized().dot(flow.direction[face].cast<double>())) >= min_cosine)
        ++agreeing;
    }
  counted = judged;
  return judged ? static_cast<double>(agreeing) / static_cast<double>(judged) : 0.0;
}

}  // namespace hair
