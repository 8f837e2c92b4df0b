#pragma once

#include "hair/extract/extract.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"

namespace hair {

/// Schema name of the extract stage's output (schemas/extract.json).
inline constexpr const char* kExtractSchema = "hairstyle.extract";

/// Members of the enum datasets /groups/patch_kind and /groups/orientation_rule.
const h5::EnumMembers& patch_kind_members();
const h5::EnumMembers& orientation_rule_members();

/// Writes everything of `result` that extract.h5 holds (schemas/extract.json), with
/// the schema attributes and the unit conventions; provenance is the caller's.
void write_extract_file(h5::File& file, const ExtractResult& result, const ExtractParams& params);

/// The body of an extract.h5 file: its mesh, and which triangles are scalp.
struct ExtractedBody {
  Points3f vertices;                    ///< #V x 3, metres
  Triangles3i triangles;                ///< #T x 3 vertex ids
  std::vector<uint8_t> scalp_triangle;  ///< #T, 1 for the scalp
};

/// Reads /body of extract.h5 after checking the file's schema.
ExtractedBody read_extracted_body(const h5::File& extract);

/// The hair mesh of extract.h5 (vertices and faces; no texture coordinates or materials)
/// with the painted flow of its faces, after checking the file's schema.
struct ExtractedPaint {
  PolyMesh mesh;
  PaintedFlow flow;
};
ExtractedPaint read_extracted_paint(const h5::File& extract);

}  // namespace hair
