// Generating a synthetic hairstyle: the streams of its components, the patches cut along
// them, and its truth (generate_model()).
#include "hair/synth/synth_model.h"

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "hair/synth/synth_component_streams.h"
#include "hair/synth/synth_head.h"
#include "hair/synth/synth_paint.h"
#include "hair/synth/synth_patches.h"
#include "hair/synth/synth_rng.h"
#include "hair/synth/synth_stream.h"
#include "hair/synth/synth_true_strands.h"

namespace hair::synth {

SynthModel generate_model(const HairStyleSpec& spec, const PolyMesh& body_m, uint32_t seed,
                          int strands_per_stream) {
  Rng rng(seed);
  Head head = measure_head(body_m);
  std::vector<Stream> streams;
  for (size_t c = 0; c < spec.components.size(); ++c) {
    const ComponentSpec& component = spec.components[c];
    int index = static_cast<int>(c);
    switch (component.kind) {
      case ComponentSpec::Kind::normal:
      case ComponentSpec::Kind::short_cards:
        add_loose_streams(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::ponytail:
        add_ponytail(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::braid:
        add_braid(component, index, spec.defects, head, rng, streams);
        break;
      case ComponentSpec::Kind::short_cap:
        add_short_cap(component, index, spec.defects, head, rng, streams);
        break;
    }
  }

  SynthModel model;
  model.name = spec.name;
  model.seed = seed;
  model.spec = spec;
  // The true strands draw from their own generator, so that their count leaves the mesh as it is.
  Rng strand_rng(seed ^ 0x5bd1e995u);
  std::vector<float> uv, positions;
  std::vector<Points3f> centres, strand_polylines;
  std::vector<int32_t> strand_stream;
  std::vector<std::vector<int32_t>> ring_streams(spec.components.size());
  for (size_t s = 0; s < streams.size(); ++s) {
    const Stream& stream = streams[s];
    auto stream_id = static_cast<int32_t>(s);
    const ComponentSpec& component = spec.components[static_cast<size_t>(stream.component)];
    const bool in_rings = component.one_piece_rings || component.one_piece_grid;
    if (in_rings) ring_streams[static_cast<size_t>(stream.component)].push_back(stream_id);
    int pieces = in_rings ? 0 : static_cast<int>(stream.pieces.size());
    for (int k = 0; k < pieces; ++k) {
      const Piece& piece = stream.pieces[static_cast<size_t>(k)];
      const bool folded = component.folded_shell_thickness_m > 0 && piece.style != HairStyle::fixed &&
                          stream.scalp_lift_m.empty();
      SynthPatch patch =
          component.tube_sides > 0
              ? build_tube_patch(stream, piece, component.tube_sides, spec.defects, rng, positions,
                                 model.mesh, uv, model.vertex_along_m)
          : folded ? build_folded_patch(stream, piece, component.folded_shell_thickness_m,
                                        spec.defects, rng, positions, model.mesh, uv,
                                        model.vertex_along_m)
                   : build_patch(stream, piece, spec.defects, head, rng, positions, model.mesh, uv,
                                 model.vertex_along_m);
      patch.stream = stream_id;
      patch.index_in_stream = k;
      // Algorithm 1 of the paper: no preceding group and no following one: root-free; no
      // preceding one: root (connected); no following one: tip; otherwise middle.
      patch.type = pieces == 1       ? GroupType::root_free
                   : k == 0          ? GroupType::root_connected
                   : k + 1 == pieces ? GroupType::tip
                                     : GroupType::middle;
      model.patches.push_back(patch);
    }
    Points3f centre(static_cast<Eigen::Index>(stream.points.size()), 3);
    for (size_t i = 0; i < stream.points.size(); ++i)
      centre.row(static_cast<Eigen::Index>(i)) = stream.points[i].cast<float>().transpose();
    centres.push_back(std::move(centre));
    model.stream_style.push_back(stream.style);
    model.stream_component.push_back(stream.component);
    add_true_strands(stream, stream_id, head, strands_per_stream, strand_rng, strand_polylines,
                     strand_stream, model.strand_point_style);
  }
  // Hair rooted under cards that stand off the head, from a generator of its own, after every
  // other true strand: those stay as they are.
  Rng under_rng(seed ^ 0x27d4eb2fu);
  for (size_t s = 0; s < streams.size(); ++s)
    if (spec.components[static_cast<size_t>(streams[s].component)].rooted_under_volume)
      add_true_strands_under_volume(streams[s], static_cast<int32_t>(s), head, strands_per_stream,
                                    spec.defects.scalp_lift_m, under_rng, strand_polylines,
                                    strand_stream, model.strand_point_style);
  for (size_t c = 0; c < ring_streams.size(); ++c) {
    const std::vector<int32_t>& ids = ring_streams[c];
    if (ids.empty()) continue;
    model.patches.push_back(spec.components[c].one_piece_grid
                                ? build_grid_patch(streams, ids, spec.defects, head, positions,
                                                   model.mesh, uv, model.vertex_along_m,
                                                   spec.components[c].grid_crown_hole_deg)
                                : build_ring_patch(streams, ids, spec.defects, head, rng, positions,
                                                   model.mesh, uv, model.vertex_along_m));
  }
  model.mesh.vertices = Eigen::Map<const Points3f>(
      positions.data(), static_cast<Eigen::Index>(positions.size() / 3), 3);
  model.mesh.corner_uv =
      Eigen::Map<const Uv2f>(uv.data(), static_cast<Eigen::Index>(uv.size() / 2), 2);
  if (spec.defects.painted_texture) {
    model.mesh.materials = {painted_hair_material(seed, spec.defects.painted_fade)};
    model.mesh.face_material.assign(static_cast<size_t>(model.mesh.face_count()), 0);
  }
  model.stream_centres = strand_set_from_polylines(centres);
  model.strands = strand_set_from_polylines(strand_polylines);
  model.strands.strand_attributes["stream"] = strand_stream;
  return model;
}

}  // namespace hair::synth
