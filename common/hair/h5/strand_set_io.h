#pragma once

#include <string>

#include "hair/core/strand_set.h"
#include "hair/h5/file.h"

namespace hair::h5 {

/// Writes `strands` into the group `group_path` (created if missing):
///   points                  #points x 3 float32, metres, root first
///   offsets                 #strands+1 int64 (CSR)
///   strand_attributes/NAME  #strands (int32 or float32) or #strands x 3 float32
///   point_attributes/NAME   #points  (int32 or float32) or #points x 3 float32
/// Large columns are chunked and compressed (see DatasetOptions).
void write_strand_set(File& file, const std::string& group_path, const StrandSet& strands);

/// Reads a strand set written by write_strand_set(). Throws bad_input naming the dataset
/// if a dataset is missing or of the wrong type or shape, if the offsets are not CSR
/// offsets of the points (start at 0, never decrease, end at #points), or if an
/// attribute column has the wrong length.
StrandSet read_strand_set(const File& file, const std::string& group_path);

}  // namespace hair::h5
