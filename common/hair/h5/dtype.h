#pragma once

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace hair::h5 {

/// Element types of the datasets that hairstyle writes. Files always store them
/// little-endian; names follow numpy ("float32", "int64").
enum class Dtype { float32, float64, int8, uint8, int32, int64 };

/// "float32", "float64", "int8", "uint8", "int32" or "int64".
std::string_view dtype_name(Dtype dtype);

/// The dtype called `name`, or nothing if no dtype has that name.
std::optional<Dtype> dtype_from_name(std::string_view name);

/// True for float32 and float64.
bool is_floating(Dtype dtype);

/// The dtype of C++ element type T (float, double, int8_t, uint8_t, int32_t, int64_t).
template <typename T>
constexpr Dtype dtype_of() {
  if constexpr (std::is_same_v<T, float>)
    return Dtype::float32;
  else if constexpr (std::is_same_v<T, double>)
    return Dtype::float64;
  else if constexpr (std::is_same_v<T, int8_t>)
    return Dtype::int8;
  else if constexpr (std::is_same_v<T, uint8_t>)
    return Dtype::uint8;
  else if constexpr (std::is_same_v<T, int32_t>)
    return Dtype::int32;
  else if constexpr (std::is_same_v<T, int64_t>)
    return Dtype::int64;
  else
    static_assert(sizeof(T) == 0, "no HDF5 dtype for this element type");
}

/// The HDF5 in-memory (native) type of `dtype`; a library constant, never closed.
hid_t memory_type(Dtype dtype);

/// The HDF5 little-endian file type of `dtype`; a library constant, never closed.
hid_t file_type(Dtype dtype);

/// The dtype a stored HDF5 type matches exactly (class, size and signedness), or
/// nothing (enums, strings, other sizes).
std::optional<Dtype> dtype_of_stored(hid_t type);

/// A short name of any stored HDF5 type for messages: a dtype name, "enum int8",
/// "int16", "float16", "string", "compound", ...
std::string stored_type_name(hid_t type);

}  // namespace hair::h5
