#include "hair/mesh/quad_recovery.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <unordered_map>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>


namespace hair {
namespace {

uint64_t directed_edge_key(int32_t from, int32_t to) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(from)) << 32) | static_cast<uint32_t>(to);
}

struct PairCandidate {
  /// How far the quad's worst corner is from a right angle in the texture's space where
  /// the mesh has UVs (a card's quads are rectangles there), else in 3D: the greedy order.
  double rank_deviation_deg;
  double worst_corner_deviation_deg;
  int64_t face_a;
  int64_t face_b;
  int corner_a;  ///< the shared edge runs from corner_a to corner_a+1 of face_a
  int corner_b;  ///< and from corner_b+1 to corner_b of face_b
  /// The shared edge is the longest of one triangle in 3D, or of both in UV: the diagonal
  /// a triangulation of a near-rectangular quad adds.
  bool longest;
};

double corner_deviation_deg(const PolyMesh& mesh, const std::array<int32_t, 4>& quad) {
  double worst = 0;
  for (int c = 0; c < 4; ++c) {
    Eigen::Vector3d here = mesh.vertices.row(quad[c]).cast<double>();
    Eigen::Vector3d to_next =
        mesh.vertices.row(quad[(c + 1) % 4]).cast<double>().transpose() - here;
    Eigen::Vector3d to_prev =
        mesh.vertices.row(quad[(c + 3) % 4]).cast<double>().transpose() - here;
    double norms = to_next.norm() * to_prev.norm();
    if (norms <= 0) return 180.0;
    double angle = std::acos(std::clamp(to_next.dot(to_prev) / norms, -1.0, 1.0));
    worst = std::max(worst, std::abs(angle * 180.0 / std::numbers::pi - 90.0));
  }
  return worst;
}

/// The worst corner's deviation from a right angle of the quad whose corners are the
/// mesh's corners `corners` in UV space; nullopt without UVs or with a degenerate corner.
std::optional<double> uv_corner_deviation_deg(const PolyMesh& mesh,
                                              const std::array<int64_t, 4>& corners) {
  if (!mesh.has_uv()) return std::nullopt;
  double worst = 0;
  for (int c = 0; c < 4; ++c) {
    auto uv = [&](int k) {
      const int64_t corner = corners[static_cast<size_t>(k % 4)];
      return Eigen::Vector2d(mesh.corner_uv(corner, 0), mesh.corner_uv(corner, 1));
    };
    const Eigen::Vector2d to_next = uv(c + 1) - uv(c), to_prev = uv(c + 3) - uv(c);
    const double norms = to_next.norm() * to_prev.norm();
    if (!(norms > 0)) return std::nullopt;
    const double angle = std::acos(std::clamp(to_next.dot(to_prev) / norms, -1.0, 1.0));
    worst = std::max(worst, std::abs(angle * 180.0 / std::numbers::pi - 90.0));
  }
  return worst;
}

double squared_edge_length(const PolyMesh& mesh, int32_t a, int32_t b) {
  return (mesh.vertices.row(a) - mesh.vertices.row(b)).squaredNorm();
}

bool is_longest_edge(const PolyMesh& mesh, std::span<const int32_t> triangle, int corner) {
  double shared = squared_edge_length(mesh, triangle[corner], triangle[(corner + 1) % 3]);
  for (int c = 0; c < 3; ++c)
    if (squared_edge_length(mesh, triangle[c], triangle[(c + 1) % 3]) > shared * (1 + 1e-6))
      return false;
  return true;
}

/// The same in the texture's space, where a card is laid out flat as a grid of
/// rectangles whatever it does in 3D: a triangulated quad of a twisted tube or card may be
/// split along its shorter diagonal in 3D, never in its UV rectangle. False without UVs.
bool is_longest_uv_edge(const PolyMesh& mesh, int64_t face, int corner) {
  if (!mesh.has_uv()) return false;
  const int64_t base = mesh.face_offsets[static_cast<size_t>(face)];
  auto squared_uv_length = [&](int from) {
    const int to = (from + 1) % 3;
    const double du = mesh.corner_uv(base + from, 0) - mesh.corner_uv(base + to, 0);
    const double dv = mesh.corner_uv(base + from, 1) - mesh.corner_uv(base + to, 1);
    return du * du + dv * dv;
  };
  const double shared = squared_uv_length(corner);
  if (!(shared > 0)) return false;
  for (int c = 0; c < 3; ++c)
    if (squared_uv_length(c) > shared * (1 + 1e-6)) return false;
  return true;
}

/// Whether the shared edge runs through one texture: its two ends have the same texture
/// coordinates in both triangles (a quad of a card is one piece of its image). True without
/// UVs.
bool same_uv_across(const PolyMesh& mesh, int64_t face_a, int corner_a, int64_t face_b,
                    int corner_b) {
  if (!mesh.has_uv()) return true;
  const int64_t base_a = mesh.face_offsets[static_cast<size_t>(face_a)];
  const int64_t base_b = mesh.face_offsets[static_cast<size_t>(face_b)];
  // a's edge runs corner_a -> corner_a+1, b's the other way: corner_b+1 -> corner_b.
  const std::array<std::pair<int64_t, int64_t>, 2> ends = {
      std::pair{base_a + corner_a, base_b + (corner_b + 1) % 3},
      std::pair{base_a + (corner_a + 1) % 3, base_b + corner_b}};
  for (auto [x, y] : ends)
    for (int k = 0; k < 2; ++k)
      if (std::abs(mesh.corner_uv(x, k) - mesh.corner_uv(y, k)) > 1e-6f) return false;
  return true;
}

/// The pairs of triangles that may make a quad (see quads_from_triangles()), in the
/// greedy order: the most rectangular first, ties broken by face id.
std::vector<PairCandidate> pair_candidates(const PolyMesh& mesh,
                                           double max_corner_deviation_deg) {
  std::unordered_map<uint64_t, std::pair<int64_t, int>> triangle_with_edge;
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_size(f) != 3) continue;
    auto triangle = mesh.face(f);
    for (int c = 0; c < 3; ++c)
      triangle_with_edge[directed_edge_key(triangle[c], triangle[(c + 1) % 3])] = {f, c};
  }

  std::vector<PairCandidate> candidates;
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_size(f) != 3) continue;
    auto triangle = mesh.face(f);
    for (int c = 0; c < 3; ++c) {
      auto found = triangle_with_edge.find(directed_edge_key(triangle[(c + 1) % 3], triangle[c]));
      if (found == triangle_with_edge.end() || found->second.first <= f) continue;
      auto [other_face, other_corner] = found->second;
      if (mesh.has_materials() && mesh.face_material[static_cast<size_t>(f)] !=
                                      mesh.face_material[static_cast<size_t>(other_face)])
        continue;  // a quad paints one image
      auto other = mesh.face(other_face);
      if (!same_uv_across(mesh, f, c, other_face, other_corner)) continue;  // a UV seam
      // Shared edge a->b in this triangle (a, b, c2), b->a in the other (b, a, d):
      // the quad is (a, d, b, c2).
      int32_t apex_other = other[(other_corner + 2) % 3];
      std::array<int32_t, 4> quad = {triangle[c], apex_other, triangle[(c + 1) % 3],
                                     triangle[(c + 2) % 3]};
      double deviation = corner_deviation_deg(mesh, quad);
      if (deviation > max_corner_deviation_deg) continue;
      const int64_t base = mesh.face_offsets[static_cast<size_t>(f)];
      const int64_t other_base = mesh.face_offsets[static_cast<size_t>(other_face)];
      const std::optional<double> uv_deviation = uv_corner_deviation_deg(
          mesh,
          {base + c, other_base + (other_corner + 2) % 3, base + (c + 1) % 3, base + (c + 2) % 3});
      const bool longest =
          is_longest_edge(mesh, triangle, c) || is_longest_edge(mesh, other, other_corner) ||
          (is_longest_uv_edge(mesh, f, c) && is_longest_uv_edge(mesh, other_face, other_corner));
      candidates.push_back(
          {uv_deviation.value_or(deviation), deviation, f, other_face, c, other_corner, longest});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
    return std::tie(x.rank_deviation_deg, x.worst_corner_deviation_deg, x.face_a, x.face_b) <
           std::tie(y.rank_deviation_deg, y.worst_corner_deviation_deg, y.face_a, y.face_b);
  });
  return candidates;
}

/// Greedy: the most rectangular pairs first, across the longest edges only. Returns each
/// face's partner among `face_count` faces (-1 for none).
std::vector<int64_t> greedy_pairs(const std::vector<PairCandidate>& candidates,
                                  size_t face_count) {
  std::vector<int64_t> partner(face_count, -1);
  for (const PairCandidate& candidate : candidates) {
    if (!candidate.longest) continue;
    if (partner[candidate.face_a] >= 0 || partner[candidate.face_b] >= 0) continue;
    partner[candidate.face_a] = candidate.face_b;
    partner[candidate.face_b] = candidate.face_a;
  }
  return partner;
}

/// A triangulated card is a perfect matching of its triangles. Where the greedy pass
/// leaves triangles alone (a quad split along its shorter diagonal, or a pair that took
/// one triangle of each of two quads and stranded their partners), Edmonds' augmenting
/// paths over every candidate re-pair along the strip until no more triangles can be
/// paired. `partner` holds the greedy pairs and receives the maximum matching.
void match_left_triangles(const std::vector<PairCandidate>& candidates,
                          std::vector<int64_t>& partner) {
  const size_t face_count = partner.size();
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
  const Vertex none = boost::graph_traits<Graph>::null_vertex();
  Graph graph(face_count);
  for (const PairCandidate& candidate : candidates)
    boost::add_edge(static_cast<Vertex>(candidate.face_a), static_cast<Vertex>(candidate.face_b),
                    graph);
  std::vector<Vertex> mate(face_count, none);
  for (size_t f = 0; f < face_count; ++f)
    if (partner[f] >= 0) mate[f] = static_cast<Vertex>(partner[f]);
  boost::edmonds_augmenting_path_finder<Graph, Vertex*,
                                        boost::property_map<Graph, boost::vertex_index_t>::type>
      augmenter(graph, mate.data(), boost::get(boost::vertex_index, graph));
  while (augmenter.augment_matching()) {
  }
  augmenter.get_current_matching(mate.data());
  for (size_t f = 0; f < face_count; ++f)
    partner[f] = mate[f] == none ? -1 : static_cast<int64_t>(mate[f]);
}

}  // namespace

QuadRecovery quads_from_triangles(const PolyMesh& mesh, double max_corner_deviation_deg) {
  const std::vector<PairCandidate> candidates = pair_candidates(mesh, max_corner_deviation_deg);
  const auto face_count = static_cast<size_t>(mesh.face_count());
  std::vector<int64_t> partner = greedy_pairs(candidates, face_count);
  match_left_triangles(candidates, partner);

  std::unordered_map<uint64_t, const PairCandidate*> candidate_of_pair;
  for (const PairCandidate& candidate : candidates)
    candidate_of_pair[directed_edge_key(static_cast<int32_t>(candidate.face_a),
                                        static_cast<int32_t>(candidate.face_b))] = &candidate;
  std::vector<std::array<int64_t, 4>> quad_corners(face_count);
  const std::vector<int64_t> matched = partner;
  std::fill(partner.begin(), partner.end(), -1);
  for (size_t f = 0; f < face_count; ++f) {
    if (matched[f] < static_cast<int64_t>(f)) continue;
    const PairCandidate& candidate = *candidate_of_pair.at(
        directed_edge_key(static_cast<int32_t>(f), static_cast<int32_t>(matched[f])));
    partner[candidate.face_a] = candidate.face_b;
    partner[candidate.face_b] = candidate.face_a;
    const int64_t base_a = mesh.face_offsets[candidate.face_a];
    const int64_t base_b = mesh.face_offsets[candidate.face_b];
    quad_corners[candidate.face_a] = {
        base_a + candidate.corner_a, base_b + (candidate.corner_b + 2) % 3,
        base_a + (candidate.corner_a + 1) % 3, base_a + (candidate.corner_a + 2) % 3};
  }

  QuadRecovery recovery;
  recovery.mesh.vertices = mesh.vertices;
  recovery.mesh.materials = mesh.materials;
  std::vector<float> uv;
  std::vector<int32_t> face;
  auto emit_corners = [&](std::span<const int64_t> corners, int64_t source_face) {
    face.clear();
    for (int64_t corner : corners) {
      face.push_back(mesh.face_vertices[corner]);
      if (mesh.has_uv()) {
        uv.push_back(mesh.corner_uv(corner, 0));
        uv.push_back(mesh.corner_uv(corner, 1));
      }
    }
    recovery.mesh.append_face(face);
    if (mesh.has_materials())
      recovery.mesh.face_material.push_back(mesh.face_material[source_face]);
    recovery.source_face.push_back(source_face);
  };
  std::vector<int64_t> corners;
  for (int64_t f = 0; f < mesh.face_count(); ++f) {
    if (partner[f] >= 0) {
      if (partner[f] < f) continue;  // emitted with its partner
      recovery.triangles_paired += 2;
      emit_corners(quad_corners[f], f);
      continue;
    }
    if (mesh.face_size(f) == 3) ++recovery.triangles_left;
    corners.clear();
    for (int64_t corner = mesh.face_offsets[f]; corner < mesh.face_offsets[f + 1]; ++corner)
      corners.push_back(corner);
    emit_corners(corners, f);
  }
  if (mesh.has_uv())
    recovery.mesh.corner_uv =
        Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  return recovery;
}

}  // namespace hair
