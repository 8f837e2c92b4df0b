#pragma once
// Meshing the pieces of streams into patches: strips and grids, tubes, folded pouches, and
// a short cap's streams as one piece (in rings round its whorl, or in a grid of latitudes
// and longitudes).

#include <cstdint>
#include <vector>

#include "hair/mesh/poly_mesh.h"
#include "hair/synth/synth_head.h"
#include "hair/synth/synth_model.h"
#include "hair/synth/synth_rng.h"
#include "hair/synth/synth_stream.h"

namespace hair::synth {

/// The patch of `piece`: rows along the stream, `piece.rails` points across; returns
/// the patch and appends its vertex positions (x, y, z each) to `positions`, the arc
/// length of each vertex to `vertex_along_m`, its faces to `mesh` and their UVs to `uv`.
SynthPatch build_patch(const Stream& stream, const Piece& piece, const DefectSpec& defects,
                       const Head& head, Rng& rng, std::vector<float>& positions, PolyMesh& mesh,
                       std::vector<float>& uv, std::vector<float>& vertex_along_m);

/// A piece meshed as a closed tube of `sides` sides round the stream's centre (diameter
/// the stream's width), as artists model ringlets: vertex (r, c) at row r along the piece
/// and angle 2 pi c / sides round it, quads between neighbouring rows and sides, the last
/// side joined to the first. Texture u runs round (0 to 1), v from the piece's root (0) to
/// its tip (1). Vertex order, triangulation and jitter as build_patch.
SynthPatch build_tube_patch(const Stream& stream, const Piece& piece, int sides,
                            const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m);

/// A piece meshed as a closed pouch (ComponentSpec::folded_shell_thickness_m): rows run
/// down the piece's front sheet (half the thickness out along the stream's normal) from
/// its start to its end, the fold's row on the centre at the end, then back up the back
/// sheet (half the thickness in) to the start; `rails` columns across the strip's width.
/// Texture u runs across (0 to 1), v from the piece's start (0) to its end (1) on both
/// sheets. Vertex order, triangulation and jitter as build_patch.
SynthPatch build_folded_patch(const Stream& stream, const Piece& piece, double thickness_m,
                              const DefectSpec& defects, Rng& rng, std::vector<float>& positions,
                              PolyMesh& mesh, std::vector<float>& uv,
                              std::vector<float>& vertex_along_m);

/// One patch for the streams `stream_ids` of a short cap meshed in rings (a wig cap):
/// vertex (k, r) on stream k at arc length r * segment_length_m, quads between
/// neighbouring streams (the last joined to the first) for rows both reach. Texture u runs
/// around, v from the whorl (0) to the longest stream's end (1), as on the other patches.
SynthPatch build_ring_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, Rng& rng, std::vector<float>& positions,
                            PolyMesh& mesh, std::vector<float>& uv,
                            std::vector<float>& vertex_along_m);

/// One patch for the streams `stream_ids` of a short cap meshed as one piece in a grid of
/// latitudes and longitudes round the head's vertical axis (rows `segment_length_m` apart
/// in polar angle from the crown, 36 columns of azimuth), as a wig cap modelled without
/// regard to how its hair runs: neither family of edges follows the hair. Faces are kept
/// where every corner lies within 1.5 cm of a stream's centre, nearest to it between its
/// ends (the hair's region, no farther than its roots and tips); the row next to the crown
/// is of triangles round the pole. Texture v is the arc length along the nearest stream
/// over the longest stream's length and u runs round the streams (the nearest stream's
/// index plus how far the point lies towards the next nearest neighbour, over the stream
/// count), so that the painted strokes, along v, follow the streams. Vertex ids run row by
/// row from the crown. With `crown_hole_deg` above 0, the faces of the rows that start
/// within that polar angle of the crown are left out: the shell is open at the crown and
/// its latitudes close round the head (quads closed on themselves: a tube).
SynthPatch build_grid_patch(const std::vector<Stream>& streams,
                            const std::vector<int32_t>& stream_ids, const DefectSpec& defects,
                            const Head& head, std::vector<float>& positions, PolyMesh& mesh,
                            std::vector<float>& uv, std::vector<float>& vertex_along_m,
                            double crown_hole_deg = 0);

}  // namespace hair::synth
