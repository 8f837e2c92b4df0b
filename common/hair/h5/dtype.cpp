#include "hair/h5/dtype.h"

#include <array>
#include <utility>

#include "hair/h5/handle.h"

namespace hair::h5 {

namespace {

constexpr std::array<std::pair<Dtype, std::string_view>, 6> kDtypeNames = {{
    {Dtype::float32, "float32"},
    {Dtype::float64, "float64"},
    {Dtype::int8, "int8"},
    {Dtype::uint8, "uint8"},
    {Dtype::int32, "int32"},
    {Dtype::int64, "int64"},
}};

/// "int16", "uint32", "float16", ... from class, size in bytes and signedness.
std::string numeric_type_name(H5T_class_t type_class, size_t size_bytes, bool is_signed) {
  const std::string bits = std::to_string(size_bytes * 8);
  if (type_class == H5T_FLOAT) return "float" + bits;
  return (is_signed ? "int" : "uint") + bits;
}

}  // namespace

std::string_view dtype_name(Dtype dtype) {
  for (const auto& [candidate, name] : kDtypeNames) {
    if (candidate == dtype) return name;
  }
  return "unknown";
}

std::optional<Dtype> dtype_from_name(std::string_view name) {
  for (const auto& [dtype, candidate] : kDtypeNames) {
    if (candidate == name) return dtype;
  }
  return std::nullopt;
}

bool is_floating(Dtype dtype) { return dtype == Dtype::float32 || dtype == Dtype::float64; }

hid_t memory_type(Dtype dtype) {
  switch (dtype) {
    case Dtype::float32:
      return H5T_NATIVE_FLOAT;
    case Dtype::float64:
      return H5T_NATIVE_DOUBLE;
    case Dtype::int8:
      return H5T_NATIVE_INT8;
    case Dtype::uint8:
      return H5T_NATIVE_UINT8;
    case Dtype::int32:
      return H5T_NATIVE_INT32;
    case Dtype::int64:
      return H5T_NATIVE_INT64;
  }
  return H5I_INVALID_HID;
}

hid_t file_type(Dtype dtype) {
  switch (dtype) {
    case Dtype::float32:
      return H5T_IEEE_F32LE;
    case Dtype::float64:
      return H5T_IEEE_F64LE;
    case Dtype::int8:
      return H5T_STD_I8LE;
    case Dtype::uint8:
      return H5T_STD_U8LE;
    case Dtype::int32:
      return H5T_STD_I32LE;
    case Dtype::int64:
      return H5T_STD_I64LE;
  }
  return H5I_INVALID_HID;
}

std::optional<Dtype> dtype_of_stored(hid_t type) {
  const H5T_class_t type_class = H5Tget_class(type);
  const size_t size_bytes = H5Tget_size(type);
  if (type_class == H5T_FLOAT) {
    if (size_bytes == 4) return Dtype::float32;
    if (size_bytes == 8) return Dtype::float64;
    return std::nullopt;
  }
  if (type_class != H5T_INTEGER) return std::nullopt;
  const bool is_signed = H5Tget_sign(type) == H5T_SGN_2;
  if (size_bytes == 1) return is_signed ? Dtype::int8 : Dtype::uint8;
  if (is_signed && size_bytes == 4) return Dtype::int32;
  if (is_signed && size_bytes == 8) return Dtype::int64;
  return std::nullopt;
}

std::string stored_type_name(hid_t type) {
  const H5T_class_t type_class = H5Tget_class(type);
  switch (type_class) {
    case H5T_INTEGER:
    case H5T_FLOAT:
      return numeric_type_name(type_class, H5Tget_size(type), H5Tget_sign(type) == H5T_SGN_2);
    case H5T_ENUM: {
      const Handle base(H5Tget_super(type), H5Tclose);
      return "enum " + stored_type_name(base.get());
    }
    case H5T_STRING:
      return "string";
    case H5T_COMPOUND:
      return "compound";
    case H5T_ARRAY:
      return "array";
    case H5T_VLEN:
      return "vlen";
    case H5T_OPAQUE:
      return "opaque";
    case H5T_REFERENCE:
      return "reference";
    case H5T_BITFIELD:
      return "bitfield";
    case H5T_TIME:
      return "time";
    default:
      return "unknown type";
  }
}

}  // namespace hair::h5
