// Meshing a short cap's streams as one piece, as wig caps are: in rings round its whorl,
// or in a grid of latitudes and longitudes that pays no heed to its hair.
#include "hair/synth/synth_patches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace hair::synth {

namespace {

/// Columns of azimuth of a short cap meshed in a grid of latitudes and longitudes.
constexpr int kGridColumns = 36;

/// Where a point lies against a stream: the nearest centre point, its arc length and
/// whether it lies between the stream's ends.
struct Nearest {
  double distance_m = std::numeric_limits<double>::infinity();
  double along_m = 0;
  bool interior = false;
};

/// The centre point of `stream` nearest to `p`.
Nearest nearest_on(const Stream& stream, const Vec3& p) {
  Nearest best;
  for (size_t i = 0; i < stream.points.size(); ++i) {
    const double d = (stream.points[i] - p).norm();
    if (d < best.distance_m) best = {d, stream.along_m[i], i > 0 && i + 1 < stream.points.size()};
  }
  return best;
}

/// A vertex of the grid: its position, texture coordinates, whether it lies in the hair's
/// region and its vertex id once numbered (-1 until then).
struct GridVertex {
  Vec3 position;
  double u = 0, v = 0;
  bool in_hair = false;
  int32_t id = -1;
};

/// The grid's vertex over the head's `surface` point (`outward` its normal), placed against
/// the streams `stream_ids` (the longest `longest_m` long): in the hair's region where the
/// nearest stream's centre lies within 1.5 cm, nearest between its ends; v the arc length
/// there over `longest_m`, u round the streams; lifted scalp_lift_m (at v = 0) to 1.5 times
/// that (at v = 1) off the scalp.
GridVertex grid_vertex(const std::vector<Stream>& streams, const std::vector<int32_t>& stream_ids,
                       const DefectSpec& defects, double longest_m, const Vec3& surface,
                       const Vec3& outward) {
  const auto count = static_cast<int>(stream_ids.size());
  GridVertex vertex;
  std::vector<Nearest> by_stream(static_cast<size_t>(count));
  int k_best = 0;
  for (int k = 0; k < count; ++k) {
    by_stream[static_cast<size_t>(k)] =
        nearest_on(streams[static_cast<size_t>(stream_ids[static_cast<size_t>(k)])], surface);
    if (by_stream[static_cast<size_t>(k)].distance_m <
        by_stream[static_cast<size_t>(k_best)].distance_m)
      k_best = k;
  }
  const Nearest& best = by_stream[static_cast<size_t>(k_best)];
  vertex.in_hair = best.interior && best.distance_m < 0.015;
  const int before = (k_best + count - 1) % count, after = (k_best + 1) % count;
  const bool towards_after = by_stream[static_cast<size_t>(after)].distance_m <=
                             by_stream[static_cast<size_t>(before)].distance_m;
  const double d_other = by_stream[static_cast<size_t>(towards_after ? after : before)].distance_m;
  const double share = best.distance_m / std::max(1e-12, best.distance_m + d_other);
  vertex.u = (k_best + (towards_after ? share : -share)) / count;
  vertex.u -= std::floor(vertex.u);
  vertex.v = std::clamp(best.along_m / longest_m, 0.0, 1.0);
  const double lift = defects.scalp_lift_m * (1.0 + 0.5 * vertex.v);
  vertex.position = surface + lift * outward;
  return vertex;
}

/// The grid's vertices row by row from the crown, rows `segment_length_m` apart in polar
/// angle down to 150 degrees: row 0 is the crown's pole, one vertex; row r > 0 has
/// kGridColumns, round the row from the face (azimuth 0).
std::vector<std::vector<GridVertex>> grid_vertices(const std::vector<Stream>& streams,
                                                   const std::vector<int32_t>& stream_ids,
                                                   const DefectSpec& defects, const Head& head,
                                                   double longest_m) {
  const double row_deg = defects.segment_length_m / head.radius_m * 180.0 / kPi;
  const int rows = static_cast<int>(std::ceil(150.0 / row_deg)) + 1;
  std::vector<std::vector<GridVertex>> grid(static_cast<size_t>(rows));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < (r == 0 ? 1 : kGridColumns); ++c) {
      const auto [surface, outward] =
          head.surface(direction(c * 360.0 / kGridColumns, r * row_deg));
      grid[static_cast<size_t>(r)].push_back(
          grid_vertex(streams, stream_ids, defects, longest_m, surface, outward));
    }
  return grid;
}

/// The faces of `grid` whose corners all lie in the hair's region, row by row from the
/// crown from row `first_row` on: triangles round the pole (row 0), quads below; their
/// corners point into `grid`.
std::vector<std::vector<GridVertex*>> faces_in_hair(std::vector<std::vector<GridVertex>>& grid,
                                                    int first_row) {
  const auto rows = static_cast<int>(grid.size());
  auto kept = [](const std::vector<GridVertex*>& corners) {
    return std::all_of(corners.begin(), corners.end(),
                       [](const GridVertex* corner) { return corner->in_hair; });
  };
  std::vector<std::vector<GridVertex*>> faces;
  for (int r = first_row; r + 1 < rows; ++r)
    for (int c = 0; c < kGridColumns; ++c) {
      auto& upper = grid[static_cast<size_t>(r)];
      auto& lower = grid[static_cast<size_t>(r + 1)];
      GridVertex* a = &lower[static_cast<size_t>(c)];
      GridVertex* b = &lower[static_cast<size_t>((c + 1) % kGridColumns)];
      std::vector<GridVertex*> corners =
          r == 0 ? std::vector<GridVertex*>{&upper[0], a, b}
                 : std::vector<GridVertex*>{&upper[static_cast<size_t>(c)], a, b,
                                            &upper[static_cast<size_t>((c + 1) % kGridColumns)]};
      if (kept(corners)) faces.push_back(std::move(corners));
    }
  return faces;
}

}  // namespace

SynthPatch build_ring_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.stream = stream_ids.front();
  patch.style = HairStyle::short_hair;
  patch.type = GroupType::root_free;
  patch.rails = static_cast<int32_t>(stream_ids.size());
  const auto count = static_cast<int>(stream_ids.size());
  double longest = 0;
  for (int32_t id : stream_ids)
    longest = std::max(longest, streams[static_cast<size_t>(id)].length_m());
  const int rows = static_cast<int>(std::floor(longest / defects.segment_length_m)) + 1;
  patch.end_m = longest;
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.first_face = mesh.face_count();
  // Vertex ids, natural order: stream by stream, root outwards; -1 beyond a stream's end.
  std::vector<std::vector<int32_t>> id(static_cast<size_t>(count));
  int32_t next = base;
  for (int k = 0; k < count; ++k) {
    const Stream& stream = streams[static_cast<size_t>(stream_ids[static_cast<size_t>(k)])];
    for (int r = 0; r < rows; ++r) {
      const double s = r * defects.segment_length_m;
      if (s > stream.length_m()) break;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p =
          on_scalp(head, stream.point_at(s), stream.scalp_lift_at(s)) + defects.jitter_m * jitter;
      for (int c = 0; c < 3; ++c) positions.push_back(static_cast<float>(p[c]));
      vertex_along_m.push_back(static_cast<float>(s));
      id[static_cast<size_t>(k)].push_back(next++);
    }
  }
  patch.vertex_count = next - base;
  auto corner = [&](int k, int r, double u) {
    uv.push_back(static_cast<float>(u));
    uv.push_back(static_cast<float>(r * defects.segment_length_m / longest));
    return id[static_cast<size_t>(k % count)][static_cast<size_t>(r)];
  };
  auto reaches = [&](int k, int r) {
    return r < static_cast<int>(id[static_cast<size_t>(k % count)].size());
  };
  for (int k = 0; k < count; ++k)
    for (int r = 0; r + 1 < rows; ++r) {
      if (!reaches(k, r + 1) || !reaches(k + 1, r + 1)) continue;
      const double u0 = static_cast<double>(k) / count, u1 = static_cast<double>(k + 1) / count;
      std::vector<int32_t> quad{corner(k, r, u0), corner(k + 1, r, u1), corner(k + 1, r + 1, u1),
                                corner(k, r + 1, u0)};
      mesh.append_face(quad);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

SynthPatch build_grid_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, std::vector<float>& positions, PolyMesh& mesh,
                            std::vector<float>& uv, std::vector<float>& vertex_along_m,
                            double crown_hole_deg) {
  SynthPatch patch;
  patch.stream = stream_ids.front();
  patch.style = HairStyle::short_hair;
  patch.type = GroupType::root_free;
  const auto count = static_cast<int>(stream_ids.size());
  patch.rails = count;
  const double row_deg = defects.segment_length_m / head.radius_m * 180.0 / kPi;
  const int first_row = crown_hole_deg > 0 ? static_cast<int>(std::ceil(crown_hole_deg / row_deg)) : 0;
  double longest = 0;
  for (int32_t id : stream_ids)
    longest = std::max(longest, streams[static_cast<size_t>(id)].length_m());
  patch.end_m = longest;
  std::vector<std::vector<GridVertex>> grid =
      grid_vertices(streams, stream_ids, defects, head, longest);
  patch.first_vertex = static_cast<int64_t>(vertex_along_m.size());
  patch.first_face = mesh.face_count();
  auto id_of = [&](GridVertex& vertex) {
    if (vertex.id < 0) {
      vertex.id = static_cast<int32_t>(vertex_along_m.size());
      for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(vertex.position[k]));
      vertex_along_m.push_back(static_cast<float>(vertex.v * longest));
    }
    return vertex.id;
  };
  // The faces kept, then their vertices numbered row by row from the crown, round each
  // row from the face (azimuth 0), as a modelling tool numbers a sphere's.
  const std::vector<std::vector<GridVertex*>> faces = faces_in_hair(grid, first_row);
  for (auto& row : grid)
    for (GridVertex& vertex : row)
      for (const auto& corners : faces)
        if (std::find(corners.begin(), corners.end(), &vertex) != corners.end()) {
          id_of(vertex);
          break;
        }
  auto face_of = [&](const std::vector<GridVertex*>& corners) {
    std::vector<int32_t> face;
    const double u0 = corners.front()->u;
    for (GridVertex* corner : corners) {
      face.push_back(id_of(*corner));
      double u = corner->u;  // unwrapped next to the first corner's
      if (u - u0 > 0.5) u -= 1;
      if (u0 - u > 0.5) u += 1;
      uv.push_back(static_cast<float>(u));
      uv.push_back(static_cast<float>(corner->v));
    }
    mesh.append_face(face);
  };
  for (const auto& corners : faces) face_of(corners);
  patch.vertex_count = static_cast<int64_t>(vertex_along_m.size()) - patch.first_vertex;
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

}  // namespace hair::synth
