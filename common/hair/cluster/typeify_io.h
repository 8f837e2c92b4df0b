#pragma once

#include "hair/cluster/typeify.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"

namespace hair {

/// Schema name of the typeify stage's output (schemas/types.json).
inline constexpr const char* kTypesSchema = "hairstyle.types";

/// What typeify reads of extract.h5.
struct ExtractedStrands {
  StrandSet strands;                        ///< /strands, root first
  std::vector<int32_t> group_first_strand;  ///< /groups/first_strand
  double head_height_m = 0;                 ///< @head_height_m
};

/// Reads the strands, groups and H of an extract.h5 file, after checking its schema.
ExtractedStrands read_extracted_strands(const h5::File& file);

/// Members of the enum dataset /groups/type, named as in the paper.
const h5::EnumMembers& group_type_members();

/// Writes types.h5 (schemas/types.json) but for provenance.
void write_types_file(h5::File& file, const GroupTypes& types, double head_height_m,
                      double neighbour_distance_m);

}  // namespace hair
