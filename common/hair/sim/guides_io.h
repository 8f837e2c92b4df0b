#pragma once
// Reading the simulate stage's inputs and writing its output, guides.h5
// (schemas/guides.json).

#include <string>

#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/sim/hair_simulation.h"

namespace hair {

/// Schema name of the simulate stage's output (schemas/guides.json).
inline constexpr const char* kGuidesSchema = "hairstyle.guides";

/// Reads the scene of simulate_hair(): the body from extract.h5, the grown strands and H
/// from strands.h5, the style of every cluster from styles.h5, after checking each file's
/// schema and that strands.h5 and styles.h5 have the same clusters.
SimulationScene read_simulation_scene(const h5::File& extract, const h5::File& strands,
                                      const h5::File& styles);

/// Members of the enum dataset /guides/kind.
const h5::EnumMembers& guide_kind_members();

/// What guides.h5 records besides the simulation itself.
struct GuidesFileInfo {
  double head_height_m = 0;
  int substeps = 1;
  std::string motion;
  std::vector<int8_t> cluster_style;
  /// Timings, left out when not set (reproducible runs).
  double guide_ms_per_frame = -1;
  double setup_s = -1;
};

/// Writes guides.h5 (schemas/guides.json) but for provenance.
void write_guides_file(h5::File& file, const SimulationResult& result, const GuidesFileInfo& info);

/// What the preview and later stages read of guides.h5.
struct SimulatedGuides {
  StrandSet rest;  ///< the guides at rest, strand attributes "kind", "style", "cluster"
  int32_t frame_count = 0;
  double fps = 0;
  std::vector<float> guide_points_m;  ///< frame_count x rest.point_count() x 3
  std::vector<RigidTransform> head;   ///< per frame
  double head_height_m = 0;
};

/// Reads guides.h5 after checking its schema.
SimulatedGuides read_simulated_guides(const h5::File& file);

}  // namespace hair
