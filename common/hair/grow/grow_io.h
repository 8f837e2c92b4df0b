#pragma once

#include <string>

#include "hair/grow/strand_growing.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"

namespace hair {

/// Schema name of the grow stage's output (schemas/strands.json).
inline constexpr const char* kStrandsSchema = "hairstyle.strands";

/// Reads what grow_strands() needs from extract.h5, types.h5 and clusters.h5, after
/// checking each file's schema and that the three describe the same strand groups.
GrowInput read_grow_input(const h5::File& extract, const h5::File& types, const h5::File& clusters);

/// Members of the enum dataset /strands/point_rule.
const h5::EnumMembers& grow_rule_members();

/// Writes strands.h5 (schemas/strands.json) but for provenance.
void write_strands_file(h5::File& file, const GrowResult& result, const GrowParams& params,
                        double head_height_m);

/// What later stages and the renderer read of strands.h5: the strands with their
/// "cluster" and "root_triangle" strand attributes, and H.
struct GrownStrands {
  StrandSet strands;
  double head_height_m = 0;
};
GrownStrands read_grown_strands(const h5::File& file);

}  // namespace hair
