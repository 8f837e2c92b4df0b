// Meshing a piece of a stream into one patch: a strip or grid, a tube or a folded pouch,
// with the vertex-order and triangulation defects drawn for it.
#include "hair/synth/synth_patches.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hair::synth {

namespace {

/// Draws a patch's vertex-order and triangulation defects (into `patch`) and returns, per
/// natural index r * columns + c, the vertex's id within the patch: natural, rows reversed
/// (numbered tip to root) or shuffled.
std::vector<int32_t> draw_vertex_ids(int rows, int columns, const DefectSpec& defects, Rng& rng,
                                     SynthPatch& patch) {
  const double draw = rng.uniform(0, 1);
  patch.order = draw < defects.reversed_share                            ? VertexOrder::reversed
                : draw < defects.reversed_share + defects.shuffled_share ? VertexOrder::shuffled
                                                                         : VertexOrder::natural;
  patch.triangulated = rng.chance(defects.triangulate_share);
  // Drawn only where asked for, so that models without it keep their random numbers.
  const bool shorter_diagonals =
      defects.shorter_diagonal_share > 0 && rng.chance(defects.shorter_diagonal_share);
  patch.shorter_diagonals = patch.triangulated && shorter_diagonals;
  std::vector<int32_t> id(static_cast<size_t>(rows * columns));  // natural index -> id in patch
  std::iota(id.begin(), id.end(), 0);
  if (patch.order == VertexOrder::reversed)
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) id[r * columns + c] = (rows - 1 - r) * columns + c;
  if (patch.order == VertexOrder::shuffled) rng.shuffle(id);
  return id;
}

/// Appends the cell between rows r, r + 1 and columns c, c + 1 as a quad, or as two
/// triangles (split from (r, c) to (r + 1, c + 1), or along the other diagonal with
/// `other_diagonal`); `corner(r, c)` gives a corner's vertex id and records its texture
/// coordinates, once per face corner, in the faces' corner order.
template <typename Corner>
void append_cell(PolyMesh& mesh, bool triangulated, Corner&& corner, int r, int c,
                 bool other_diagonal = false) {
  if (triangulated && other_diagonal) {
    std::vector<int32_t> first{corner(r, c), corner(r, c + 1), corner(r + 1, c)};
    mesh.append_face(first);
    std::vector<int32_t> second{corner(r, c + 1), corner(r + 1, c + 1), corner(r + 1, c)};
    mesh.append_face(second);
  } else if (triangulated) {
    std::vector<int32_t> first{corner(r, c), corner(r, c + 1), corner(r + 1, c + 1)};
    mesh.append_face(first);
    std::vector<int32_t> second{corner(r, c), corner(r + 1, c + 1), corner(r + 1, c)};
    mesh.append_face(second);
  } else {
    std::vector<int32_t> quad{corner(r, c), corner(r, c + 1), corner(r + 1, c + 1),
                              corner(r + 1, c)};
    mesh.append_face(quad);
  }
}

}  // namespace

SynthPatch build_patch(const Stream& stream, const Piece& piece, const DefectSpec& defects,
                       const Head& head, Rng& rng, std::vector<float>& positions, PolyMesh& mesh,
                       std::vector<float>& uv, std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = std::max(2, piece.rails);
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  int columns = patch.rails;
  int rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  int count = rows * columns;
  const std::vector<int32_t> id = draw_vertex_ids(rows, columns, defects, rng, patch);
  // Drawn from a generator of its own, seeded by the patch's first vertex: a spec with
  // tucked tips draws every other defect as the same spec without them.
  patch.tucked = defects.tucked_share > 0 && !stream.scalp_lift_m.empty() &&
                 piece.end_m >= stream.length_m() - 1e-9 &&
                 Rng(static_cast<uint32_t>(vertex_along_m.size()) * 2654435761u ^ 0x7f4a7c15u)
                     .chance(defects.tucked_share);
  const double tuck_start_m = piece.end_m - defects.tuck_length_m;

  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  for (int r = 0; r < rows; ++r) {
    double s = piece.start_m + (piece.end_m - piece.start_m) * r / (rows - 1);
    Vec3 centre = stream.point_at(s), across = stream.across_at(s);
    double width = stream.width_at(s);
    for (int c = 0; c < columns; ++c) {
      double u = static_cast<double>(c) / (columns - 1) - 0.5;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p = centre + u * width * across;
      if (!stream.scalp_lift_m.empty()) {
        double lift_m = stream.scalp_lift_at(s);
        if (patch.tucked && s > tuck_start_m) {
          const double t = std::min(1.0, (s - tuck_start_m) / defects.tuck_length_m);
          lift_m = (1 - t) * lift_m - t * defects.tuck_depth_m;
        }
        p = on_scalp(head, p, lift_m);
      }
      p += defects.jitter_m * jitter;
      int32_t v = base + id[static_cast<size_t>(r * columns + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(columns - 1));
    uv.push_back(static_cast<float>(r) / static_cast<float>(rows - 1));
    return base + id[static_cast<size_t>(r * columns + c)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * columns + c)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

SynthPatch build_tube_patch(const Stream& stream, const Piece& piece, int sides,
                            const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = sides;
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  int rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  int count = rows * sides;
  const std::vector<int32_t> id = draw_vertex_ids(rows, sides, defects, rng, patch);
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  for (int r = 0; r < rows; ++r) {
    double s = piece.start_m + (piece.end_m - piece.start_m) * r / (rows - 1);
    Vec3 centre = stream.point_at(s), across = stream.across_at(s), normal = stream.normal_at(s);
    double radius = 0.5 * stream.width_at(s);
    for (int c = 0; c < sides; ++c) {
      double angle = 2 * kPi * c / sides;
      Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      Vec3 p = centre + radius * (std::cos(angle) * across + std::sin(angle) * normal) +
               defects.jitter_m * jitter;
      int32_t v = base + id[static_cast<size_t>(r * sides + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(sides));
    uv.push_back(static_cast<float>(r) / static_cast<float>(rows - 1));
    return base + id[static_cast<size_t>(r * sides + c % sides)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * sides + c % sides)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c < sides; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

SynthPatch build_folded_patch(const Stream& stream, const Piece& piece, double thickness_m,
                              const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                              PolyMesh& mesh, std::vector<float>& uv,
                              std::vector<float>& vertex_along_m) {
  SynthPatch patch;
  patch.style = piece.style;
  patch.rails = std::max(2, piece.rails);
  patch.start_m = piece.start_m;
  patch.end_m = piece.end_m;
  const int columns = patch.rails;
  const int sheet_rows = std::max(
      2,
      static_cast<int>(std::lround((piece.end_m - piece.start_m) / defects.segment_length_m)) + 1);
  const int rows = 2 * sheet_rows - 1;  // the fold's row is shared by both sheets
  const int count = rows * columns;
  const std::vector<int32_t> id = draw_vertex_ids(rows, columns, defects, rng, patch);
  auto base = static_cast<int32_t>(vertex_along_m.size());
  patch.first_vertex = base;
  patch.vertex_count = count;
  patch.first_face = mesh.face_count();
  positions.resize(3 * static_cast<size_t>(base + count));
  vertex_along_m.resize(static_cast<size_t>(base + count));
  // Row r lies at the piece's fraction along() and on the sheet side() (+1 front, -1 back).
  const auto along = [&](int r) {
    const int k = r < sheet_rows ? r : rows - 1 - r;
    return static_cast<double>(k) / (sheet_rows - 1);
  };
  const auto side = [&](int r) { return r + 1 < sheet_rows ? 1.0 : r + 1 == sheet_rows ? 0.0 : -1.0; };
  for (int r = 0; r < rows; ++r) {
    const double s = piece.start_m + (piece.end_m - piece.start_m) * along(r);
    const Vec3 centre = stream.point_at(s), across = stream.across_at(s),
               normal = stream.normal_at(s);
    const double width = stream.width_at(s);
    for (int c = 0; c < columns; ++c) {
      const double u = static_cast<double>(c) / (columns - 1) - 0.5;
      const Vec3 jitter(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      const Vec3 p = centre + u * width * across + 0.5 * thickness_m * side(r) * normal +
                     defects.jitter_m * jitter;
      const int32_t v = base + id[static_cast<size_t>(r * columns + c)];
      for (int k = 0; k < 3; ++k)
        positions[3 * static_cast<size_t>(v) + static_cast<size_t>(k)] = static_cast<float>(p[k]);
      vertex_along_m[static_cast<size_t>(v)] = static_cast<float>(s);
    }
  }
  auto corner = [&](int r, int c) {
    uv.push_back(static_cast<float>(c) / static_cast<float>(columns - 1));
    uv.push_back(static_cast<float>(along(r)));
    return base + id[static_cast<size_t>(r * columns + c)];
  };
  const auto position = [&](int r, int c) {
    const auto v = static_cast<size_t>(base + id[static_cast<size_t>(r * columns + c)]);
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const bool other = patch.shorter_diagonals &&
                         (position(r, c + 1) - position(r + 1, c)).squaredNorm() <
                             (position(r, c) - position(r + 1, c + 1)).squaredNorm();
      append_cell(mesh, patch.triangulated, corner, r, c, other);
    }
  patch.face_count = mesh.face_count() - patch.first_face;
  return patch;
}

}  // namespace hair::synth
