#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "hair/h5/file.h"

namespace hair::h5 {

/// Called with the flat (row-major) index of the first value of a block and the block's
/// values; returns false to stop reading.
template <typename T>
using BlockVisitor = std::function<bool(int64_t first_index, std::span<const T> values)>;

/// Reads the numeric dataset `path` in blocks of whole rows of its first dimension, about
/// `block_elements` values at a time, converted to T, and hands each block to `visit` in
/// order until it returns false; memory stays bounded for datasets of any size. T is double (any
/// integer or float dataset; float32 NaN and Inf are kept) or int64_t (integer datasets only).
/// Throws bad_input if the dataset is missing or not of a convertible type.
template <typename T>
void for_each_block(const File& file, const std::string& path, const BlockVisitor<T>& visit,
                    int64_t block_elements = int64_t{1} << 20);

}  // namespace hair::h5
