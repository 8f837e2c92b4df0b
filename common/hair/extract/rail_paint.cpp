#include "hair/extract/rail_paint.h"

#include <cmath>

namespace hair {
namespace {

uint64_t edge_key(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

bool flow_is_clear(const PaintedFlow& flow, int64_t face) {
  return face >= 0 && flow.coherence[static_cast<size_t>(face)] >= kClearFlowCoherence;
}

}  // namespace

EdgeFaces::EdgeFaces(const PolyMesh& mesh) {
  faces_.reserve(static_cast<size_t>(2 * mesh.face_count()));
  for (int64_t face = 0; face < mesh.face_count(); ++face) {
    const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
    const int corners = mesh.face_size(face);
    for (int c = 0; c < corners; ++c) {
      int32_t a = mesh.face_vertices[static_cast<size_t>(first + c)];
      int32_t b = mesh.face_vertices[static_cast<size_t>(first + (c + 1) % corners)];
      auto [it, inserted] = faces_.try_emplace(edge_key(a, b), std::array<int64_t, 2>{face, -1});
      if (!inserted && it->second[1] < 0 && it->second[0] != face) it->second[1] = face;
    }
  }
}

std::array<int64_t, 2> EdgeFaces::faces(int32_t a, int32_t b) const {
  auto it = faces_.find(edge_key(a, b));
  return it == faces_.end() ? std::array<int64_t, 2>{-1, -1} : it->second;
}

std::vector<std::vector<std::array<FamilyPaint, 2>>> family_paint(
    const PolyMesh& mesh, const PaintedFlow& flow, const EdgeFaces& edge_faces,
    const std::vector<PatchTopology>& topologies) {
  std::vector<std::vector<std::array<FamilyPaint, 2>>> paint(topologies.size());
  for (size_t p = 0; p < topologies.size(); ++p) paint[p].resize(topologies[p].regions.size());
  if (flow.coherence.size() != static_cast<size_t>(mesh.face_count()) ||
      flow.painted_face_count() == 0)
    return paint;
  const double min_cosine = std::cos(kFlowAgreementAngleDeg * M_PI / 180);
#pragma omp parallel for schedule(dynamic)
  for (size_t p = 0; p < topologies.size(); ++p)
    for (size_t r = 0; r < topologies[p].regions.size(); ++r)
      for (size_t f = 0; f < 2; ++f) {
        double total = 0, judged = 0, along = 0;
        for (const auto& chain : topologies[p].regions[r].families[f].chains)
          for (size_t i = 1; i < chain.size(); ++i) {
            Eigen::Vector3f edge = mesh.vertices.row(chain[i]) - mesh.vertices.row(chain[i - 1]);
            const double length = edge.norm();
            if (!(length > 0)) continue;
            total += length;
            double clear = 0, agreeing = 0;
            for (int64_t face : edge_faces.faces(chain[i - 1], chain[i])) {
              if (!flow_is_clear(flow, face)) continue;
              clear += 1;
              const double cosine =
                  std::abs(edge.dot(flow.direction[static_cast<size_t>(face)])) / length;
              agreeing += cosine >= min_cosine ? 1 : 0;
            }
            if (clear == 0) continue;
            judged += length;
            along += length * agreeing / clear;
          }
        FamilyPaint& result = paint[p][r][f];
        result.judged_share = total > 0 ? judged / total : 0;
        result.along_share = judged > 0 ? along / judged : 0;
      }
  return paint;
}

int family_along_paint(const std::array<FamilyPaint, 2>& paint, double min_judged_share,
                       double min_along_gap) {
  if (paint[0].judged_share < min_judged_share || paint[1].judged_share < min_judged_share)
    return -1;
  const double gap = paint[0].along_share - paint[1].along_share;
  if (std::abs(gap) < min_along_gap) return -1;
  return gap > 0 ? 0 : 1;
}

AlphaFade rails_alpha_fade(const PolyMesh& mesh, const PaintedFlow& flow,
                           const EdgeFaces& edge_faces,
                           const std::vector<std::vector<int32_t>>& rails) {
  AlphaFade fade;
  if (flow.coherence.size() != static_cast<size_t>(mesh.face_count())) return fade;
  double signed_sum = 0, magnitude_sum = 0;
  for (const auto& rail : rails) {
    const int64_t edges_before = fade.judged_edges;
    for (size_t i = 1; i < rail.size(); ++i) {
      Eigen::Vector3f edge = mesh.vertices.row(rail[i]) - mesh.vertices.row(rail[i - 1]);
      if (!(edge.norm() > 0)) continue;
      double fall = 0;
      int clear = 0;
      for (int64_t face : edge_faces.faces(rail[i - 1], rail[i])) {
        if (!flow_is_clear(flow, face)) continue;
        ++clear;
        // direction points the way the alpha falls; the fall along this edge:
        const double cosine = edge.dot(flow.direction[static_cast<size_t>(face)]) / edge.norm();
        fall += cosine * flow.alpha_fall[static_cast<size_t>(face)];
      }
      if (clear == 0) continue;
      fall /= clear;
      signed_sum += fall;
      magnitude_sum += std::abs(fall);
      ++fade.judged_edges;
    }
    if (fade.judged_edges > edges_before) ++fade.judged_rails;
  }
  if (magnitude_sum > 0) fade.vote = signed_sum / magnitude_sum;
  if (fade.judged_edges > 0)
    fade.mean_fall = magnitude_sum / static_cast<double>(fade.judged_edges);
  if (fade.judged_rails > 0)
    fade.mean_rail_fall = magnitude_sum / static_cast<double>(fade.judged_rails);
  return fade;
}

}  // namespace hair
