#pragma once
// Exports of strands that hair tools read, and readers for the round-trip tests:
// OBJ polylines, cyHair .hair (Cem Yuksel's format), and ASCII USD (.usda) BasisCurves
// with animated points and the Alembic groom attributes (groom_id, groom_guide,
// groom_root_uv, width) as primvars. docs/interpolate.md describes the mapping.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Writes `strands` as an OBJ file of polylines: a `v x y z` line per point (metres, 9
/// significant digits, so float32 values read back exactly) and an `l i j` line per
/// segment of every strand (1-based; a strand's segments share their vertices), which
/// every OBJ importer reads whole (Blender 3.4's keeps only the ends of a longer `l`
/// line). Throws Error::runtime naming `path` if it cannot be written.
void write_obj_polylines(const std::filesystem::path& path, const StrandSet& strands,
                         const std::string& comment = {});

/// Reads the `v` and `l` lines of an OBJ file as strands: an `l` line that starts at the
/// vertex the one before it ended at goes on with it (segments written one per line),
/// otherwise it starts a strand; in order. Throws Error::bad_input naming the file and
/// line for what it cannot read.
StrandSet read_obj_polylines(const std::filesystem::path& path);

/// Writes `strands` as a cyHair file (.hair, www.cemyuksel.com/research/hairmodels): a
/// 128-byte header ("HAIR", counts, the arrays present: segments, points, thickness),
/// the segments per strand (uint16), the points (float32 xyz), a thickness per point
/// (`thickness_m`, may be empty for none). Throws Error::usage for a strand of more than
/// 65,536 points or of fewer than 2, Error::runtime if the file cannot be written.
void write_cyhair(const std::filesystem::path& path, const StrandSet& strands,
                  const std::vector<float>& thickness_m, const std::string& info = {});

/// Reads a cyHair file's strands (with its default segment count where it has no segments
/// array). Throws Error::bad_input naming the file for a wrong signature or a short file.
StrandSet read_cyhair(const std::filesystem::path& path);

/// What write_usda() writes besides the points.
struct UsdaCurves {
  std::vector<int64_t> offsets;          ///< CSR offsets of the strands (#strands + 1)
  std::vector<int32_t> groom_id;         ///< per strand
  std::vector<int32_t> groom_guide;      ///< per strand: 1 for a strand that is a guide
  std::vector<Eigen::Vector2f> root_uv;  ///< per strand
  std::vector<int32_t> cluster;          ///< per strand
  std::vector<int32_t> style;            ///< per strand (HairStyle values, -1 none)
  std::vector<float> width_m;            ///< per point
  double fps = 30;
  std::string comment;  ///< goes into the layer's doc string
};

/// Writes the rest groom as an ASCII USD layer: /Groom (Xform, metres: metersPerUnit 1,
/// Y up) with a BasisCurves prim "Strands" (type linear, curveVertexCounts, the points
/// `rest_points` (#points x 3) in their shortest exact text, widths per vertex to three
/// digits, the primvars groom_id, groom_guide, groom_root_uv, cluster and style per
/// curve), no animation. Throws Error::runtime naming `path`.
void write_usda_groom(const std::filesystem::path& path, const UsdaCurves& curves,
                      const Points3f& rest_points);

/// Writes an ASCII USD layer of the points' animation over the groom layer `groom_layer`
/// (its path as the layer names it, relative to this layer's folder, in subLayers): an
/// `over` of /Groom/Strands whose points are time-sampled at `frames` (time codes, per
/// second `fps`) by `frame_points(k)` (#points x 3 of the k-th frame). Opening it gives
/// the animated groom. Throws Error::runtime naming `path`.
void write_usda_animation(const std::filesystem::path& path, const std::string& groom_layer,
                          double fps, const std::string& comment,
                          const std::vector<int64_t>& frames,
                          const std::function<Points3f(size_t)>& frame_points);

}  // namespace hair
