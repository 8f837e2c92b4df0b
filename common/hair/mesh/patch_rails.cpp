#include "hair/mesh/patch_rails.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <unordered_map>

namespace hair {
namespace {

uint64_t undirected_edge_key(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

/// The patch's faces and edges with local ids.
struct LocalEdges {
  std::vector<std::array<int32_t, 2>> edge_vertices;  ///< #edges (a, b) as first met
  std::vector<std::vector<int32_t>> edge_faces;       ///< #edges local face ids
  std::vector<std::vector<int32_t>> face_edges;       ///< #faces edge ids by corner
};

LocalEdges local_edges(const PolyMesh& mesh, std::span<const int64_t> faces) {
  LocalEdges local;
  std::unordered_map<uint64_t, int32_t> edge_of_key;
  local.face_edges.resize(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    auto vertex_ids = mesh.face(faces[i]);
    for (size_t k = 0; k < vertex_ids.size(); ++k) {
      int32_t a = vertex_ids[k];
      int32_t b = vertex_ids[(k + 1) % vertex_ids.size()];
      auto [it, inserted] = edge_of_key.try_emplace(
          undirected_edge_key(a, b), static_cast<int32_t>(local.edge_vertices.size()));
      if (inserted) {
        local.edge_vertices.push_back({a, b});
        local.edge_faces.emplace_back();
      }
      local.face_edges[i].push_back(it->second);
      local.edge_faces[it->second].push_back(static_cast<int32_t>(i));
    }
  }
  return local;
}

/// Colours the edges of the quads in two families by breadth-first search, region
/// by region (quads connected through edges). Returns the region of each face (-1
/// for faces that are not quads) and the family of each edge (-1 when not on a quad).
struct EdgeColouring {
  std::vector<int32_t> face_region;
  std::vector<int8_t> edge_family;
  int32_t region_count = 0;
  int32_t conflicts = 0;
};

EdgeColouring colour_edges(const LocalEdges& local) {
  EdgeColouring colouring;
  size_t face_count = local.face_edges.size();
  colouring.face_region.assign(face_count, -1);
  colouring.edge_family.assign(local.edge_vertices.size(), -1);
  auto is_quad = [&](size_t i) { return local.face_edges[i].size() == 4; };
  for (size_t seed = 0; seed < face_count; ++seed) {
    if (!is_quad(seed) || colouring.face_region[seed] >= 0) continue;
    int32_t region = colouring.region_count++;
    std::deque<int32_t> queue{static_cast<int32_t>(seed)};
    colouring.face_region[seed] = region;
    while (!queue.empty()) {
      int32_t face = queue.front();
      queue.pop_front();
      const auto& edges = local.face_edges[face];
      // Edges 0 and 2 in one family, 1 and 3 in the other; keep the assignment
      // that agrees with more of the edges already coloured.
      int agree = 0, disagree = 0;
      for (int k = 0; k < 4; ++k) {
        int8_t family = colouring.edge_family[edges[k]];
        if (family >= 0) (family == k % 2 ? agree : disagree)++;
      }
      int flip = disagree > agree ? 1 : 0;
      bool conflict = false;
      for (int k = 0; k < 4; ++k) {
        int8_t wanted = static_cast<int8_t>((k % 2) ^ flip);
        int8_t& family = colouring.edge_family[edges[k]];
        if (family < 0)
          family = wanted;
        else if (family != wanted)
          conflict = true;
      }
      colouring.conflicts += conflict ? 1 : 0;
      for (int32_t edge : edges)
        for (int32_t neighbour : local.edge_faces[edge])
          if (is_quad(neighbour) && colouring.face_region[neighbour] < 0) {
            colouring.face_region[neighbour] = region;
            queue.push_back(neighbour);
          }
    }
  }
  return colouring;
}

/// Walks the chains of the edges `in_family` (edge ids): through vertices with exactly
/// two such edges, ending elsewhere. Deterministic: starts at the lowest vertex ids.
std::vector<std::vector<int32_t>> edge_chains(const LocalEdges& local,
                                              const std::vector<int32_t>& in_family) {
  std::map<int32_t, std::vector<int32_t>> vertex_edges;  // ordered: deterministic starts
  for (int32_t edge : in_family)
    for (int32_t v : local.edge_vertices[edge]) vertex_edges[v].push_back(edge);
  std::unordered_map<int32_t, bool> visited;
  for (int32_t edge : in_family) visited[edge] = false;

  std::vector<std::vector<int32_t>> chains;
  auto walk = [&](int32_t start, int32_t first_edge) {
    std::vector<int32_t> chain{start};
    int32_t vertex = start;
    int32_t edge = first_edge;
    while (true) {
      visited[edge] = true;
      const auto& ends = local.edge_vertices[edge];
      vertex = ends[0] == vertex ? ends[1] : ends[0];
      chain.push_back(vertex);
      const auto& at_vertex = vertex_edges[vertex];
      if (at_vertex.size() != 2) break;
      edge = at_vertex[0] == edge ? at_vertex[1] : at_vertex[0];
      if (visited[edge]) break;
    }
    chains.push_back(std::move(chain));
  };
  for (const auto& [vertex, edges] : vertex_edges)
    if (edges.size() != 2)
      for (int32_t edge : edges)
        if (!visited[edge]) walk(vertex, edge);
  for (const auto& [vertex, edges] : vertex_edges)  // what is left are closed rings
    for (int32_t edge : edges)
      if (!visited[edge]) walk(vertex, edge);
  return chains;
}

double polyline_length(const PolyMesh& mesh, const std::vector<int32_t>& chain) {
  double length = 0;
  for (size_t i = 1; i < chain.size(); ++i)
    length += (mesh.vertices.row(chain[i]) - mesh.vertices.row(chain[i - 1])).cast<double>().norm();
  return length;
}

/// Edge id -> (chain, vertex the chain leaves the edge from).
std::unordered_map<int32_t, std::pair<int32_t, int32_t>> edge_traversal(
    const std::vector<std::vector<int32_t>>& chains,
    const std::unordered_map<uint64_t, int32_t>& edge_of_key) {
  std::unordered_map<int32_t, std::pair<int32_t, int32_t>> traversal;
  for (size_t c = 0; c < chains.size(); ++c)
    for (size_t i = 1; i < chains[c].size(); ++i)
      traversal[edge_of_key.at(undirected_edge_key(chains[c][i - 1], chains[c][i]))] = {
          static_cast<int32_t>(c), chains[c][i - 1]};
  return traversal;
}

/// Orients the chains of one family consistently: in every quad the two edges of the
/// family are parallel (v0->v1 matches v3->v2), so the chains through them must run
/// the same way. Breadth-first over chains from the first.
void orient_chains_consistently(const PolyMesh& mesh, std::span<const int64_t> faces,
                                const LocalEdges& local,
                                const std::unordered_map<uint64_t, int32_t>& edge_of_key,
                                const std::vector<int32_t>& quads, int family,
                                const std::vector<int8_t>& edge_family,
                                std::vector<std::vector<int32_t>>& chains) {
  auto traversal = edge_traversal(chains, edge_of_key);
  // relation[c] lists (other chain, +1 same direction / -1 opposite).
  std::vector<std::vector<std::pair<int32_t, int>>> relation(chains.size());
  for (int32_t face : quads) {
    auto v = mesh.face(faces[face]);
    const auto& edges = local.face_edges[face];
    int first = edge_family[edges[0]] == family ? 0 : 1;
    // Parallel pair: edge `first` (v[first] -> v[first+1]) and edge first+2 traversed
    // from v[first+3] to v[first+2].
    int32_t edge_a = edges[first], edge_b = edges[first + 2];
    auto found_a = traversal.find(edge_a), found_b = traversal.find(edge_b);
    if (found_a == traversal.end() || found_b == traversal.end()) continue;
    auto [chain_a, from_a] = found_a->second;
    auto [chain_b, from_b] = found_b->second;
    if (chain_a == chain_b) continue;
    int direction_a = from_a == v[first] ? 1 : -1;
    int direction_b = from_b == v[(first + 3) % 4] ? 1 : -1;
    relation[chain_a].push_back({chain_b, direction_a * direction_b});
    relation[chain_b].push_back({chain_a, direction_a * direction_b});
  }
  std::vector<int> sign(chains.size(), 0);
  for (size_t seed = 0; seed < chains.size(); ++seed) {
    if (sign[seed] != 0) continue;
    sign[seed] = 1;
    std::deque<int32_t> queue{static_cast<int32_t>(seed)};
    while (!queue.empty()) {
      int32_t chain = queue.front();
      queue.pop_front();
      for (auto [other, same] : relation[chain])
        if (sign[other] == 0) {
          sign[other] = sign[chain] * same;
          queue.push_back(other);
        }
    }
  }
  for (size_t c = 0; c < chains.size(); ++c)
    if (sign[c] < 0) std::reverse(chains[c].begin(), chains[c].end());
}

/// Texture statistics of a family's oriented chains; see EdgeFamily.
void texture_statistics(const PolyMesh& mesh, std::span<const int64_t> faces,
                        const LocalEdges& local,
                        const std::unordered_map<uint64_t, int32_t>& edge_of_key,
                        const std::vector<int32_t>& quads, int family,
                        const std::vector<int8_t>& edge_family, EdgeFamily& result) {
  if (!mesh.has_uv()) return;
  auto traversal = edge_traversal(result.chains, edge_of_key);
  double alignment_sum = 0, growth_sum = 0;
  int64_t samples = 0;
  for (int32_t face : quads) {
    int64_t base = mesh.face_offsets[faces[face]];
    auto v = mesh.face(faces[face]);
    for (int k = 0; k < 4; ++k) {
      int32_t edge = local.face_edges[face][k];
      if (edge_family[edge] != family) continue;
      Eigen::Vector2f delta = mesh.corner_uv.row(base + (k + 1) % 4) - mesh.corner_uv.row(base + k);
      float extent = std::abs(delta.x()) + std::abs(delta.y());
      if (extent <= 0) continue;
      auto found = traversal.find(edge);
      int direction = found != traversal.end() && found->second.second != v[k] ? -1 : 1;
      alignment_sum += std::abs(delta.y()) / extent;
      growth_sum += direction * delta.y() / extent;
      ++samples;
    }
  }
  if (samples == 0) return;
  result.v_alignment = alignment_sum / static_cast<double>(samples);
  result.v_growth = growth_sum / static_cast<double>(samples);
}

}  // namespace

PatchTopology patch_topology(const PolyMesh& mesh, std::span<const int64_t> faces) {
  PatchTopology topology;
  topology.face_count = static_cast<int64_t>(faces.size());
  LocalEdges local = local_edges(mesh, faces);
  EdgeColouring colouring = colour_edges(local);
  topology.family_conflicts = colouring.conflicts;

  std::vector<std::vector<int32_t>> region_quads(colouring.region_count);
  for (size_t i = 0; i < faces.size(); ++i) {
    if (colouring.face_region[i] >= 0)
      region_quads[colouring.face_region[i]].push_back(static_cast<int32_t>(i));
    else
      ++topology.non_quad_faces;
  }

  // Poles: interior vertices (on no boundary edge) where other than four quads meet.
  std::unordered_map<int32_t, int> quads_at_vertex;
  std::unordered_map<int32_t, bool> on_boundary;
  for (size_t e = 0; e < local.edge_vertices.size(); ++e)
    if (local.edge_faces[e].size() == 1)
      for (int32_t v : local.edge_vertices[e]) on_boundary[v] = true;
  for (size_t i = 0; i < faces.size(); ++i)
    if (colouring.face_region[i] >= 0)
      for (int32_t v : mesh.face(faces[i])) ++quads_at_vertex[v];
  for (const auto& [vertex, count] : quads_at_vertex)
    if (count != 4 && !on_boundary.contains(vertex)) ++topology.interior_poles;

  // The patch's edges by their vertices, once for every region (a patch of many regions
  // would otherwise build it again for each: time that grows with their product).
  std::unordered_map<uint64_t, int32_t> edge_of_key;
  for (size_t e = 0; e < local.edge_vertices.size(); ++e)
    edge_of_key[undirected_edge_key(local.edge_vertices[e][0], local.edge_vertices[e][1])] =
        static_cast<int32_t>(e);

  for (int32_t region = 0; region < colouring.region_count; ++region) {
    QuadRegion quad_region;
    quad_region.quad_count = static_cast<int64_t>(region_quads[region].size());
    std::array<std::vector<int32_t>, 2> family_edges;
    std::vector<bool> taken(local.edge_vertices.size(), false);
    for (int32_t face : region_quads[region])
      for (int32_t edge : local.face_edges[face])
        if (!taken[edge]) {
          taken[edge] = true;
          family_edges[colouring.edge_family[edge]].push_back(edge);
        }
    for (int family = 0; family < 2; ++family) {
      EdgeFamily& result = quad_region.families[family];
      result.chains = edge_chains(local, family_edges[family]);
      orient_chains_consistently(mesh, faces, local, edge_of_key, region_quads[region], family,
                                 colouring.edge_family, result.chains);
      double total_length = 0;
      for (const auto& chain : result.chains) {
        total_length += polyline_length(mesh, chain);
        if (chain.size() > 2 && chain.front() == chain.back()) ++result.closed_chain_count;
      }
      result.mean_chain_length =
          result.chains.empty() ? 0.0 : total_length / static_cast<double>(result.chains.size());
      texture_statistics(mesh, faces, local, edge_of_key, region_quads[region], family,
                         colouring.edge_family, result);
    }
    topology.regions.push_back(std::move(quad_region));
  }
  return topology;
}

PatchKind patch_kind(const PatchTopology& topology, std::span<const int> along_family) {
  int64_t quad_faces = topology.face_count - topology.non_quad_faces;
  if (topology.regions.empty() || topology.non_quad_faces > quad_faces)
    return PatchKind::triangle_soup;
  bool strip = true;
  for (size_t r = 0; r < topology.regions.size(); ++r) {
    const EdgeFamily& across = topology.regions[r].families[1 - along_family[r]];
    if (across.closed_chain_count > 0) return PatchKind::tube;
    for (const auto& chain : across.chains) strip &= chain.size() == 2;
    strip &= topology.regions[r].families[along_family[r]].chains.size() == 2;
  }
  if (topology.interior_poles > 0) return PatchKind::cap;
  return strip ? PatchKind::strip : PatchKind::grid;
}

Points3f principal_axis_polyline(const PolyMesh& mesh, std::span<const int64_t> faces) {
  std::vector<int32_t> vertex_ids;
  for (int64_t face : faces)
    for (int32_t v : mesh.face(face)) vertex_ids.push_back(v);
  std::sort(vertex_ids.begin(), vertex_ids.end());
  vertex_ids.erase(std::unique(vertex_ids.begin(), vertex_ids.end()), vertex_ids.end());

  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int32_t v : vertex_ids) mean += mesh.vertices.row(v).cast<double>().transpose();
  mean /= static_cast<double>(vertex_ids.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (int32_t v : vertex_ids) {
    Eigen::Vector3d d = mesh.vertices.row(v).cast<double>().transpose() - mean;
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Vector3d axis = solver.eigenvectors().col(2);

  std::vector<double> along(vertex_ids.size());
  for (size_t i = 0; i < vertex_ids.size(); ++i)
    along[i] = (mesh.vertices.row(vertex_ids[i]).cast<double>().transpose() - mean).dot(axis);
  auto [min_it, max_it] = std::minmax_element(along.begin(), along.end());
  double low = *min_it, high = *max_it;
  int bin_count = std::clamp(static_cast<int>(vertex_ids.size()) / 3, 2, 16);
  std::vector<Eigen::Vector3d> sums(bin_count, Eigen::Vector3d::Zero());
  std::vector<int> counts(bin_count, 0);
  for (size_t i = 0; i < vertex_ids.size(); ++i) {
    double t = high > low ? (along[i] - low) / (high - low) : 0.0;
    int bin = std::min(bin_count - 1, static_cast<int>(t * bin_count));
    sums[bin] += mesh.vertices.row(vertex_ids[i]).cast<double>().transpose();
    ++counts[bin];
  }
  std::vector<Eigen::Vector3d> centroids;
  for (int bin = 0; bin < bin_count; ++bin)
    if (counts[bin] > 0) centroids.push_back(sums[bin] / counts[bin]);
  if (centroids.size() < 2) centroids = {mean + low * axis, mean + high * axis};
  Points3f polyline(static_cast<Eigen::Index>(centroids.size()), 3);
  for (size_t i = 0; i < centroids.size(); ++i)
    polyline.row(static_cast<Eigen::Index>(i)) = centroids[i].cast<float>().transpose();
  return polyline;
}

}  // namespace hair
