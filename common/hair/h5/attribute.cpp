#include "hair/h5/attribute.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "hair/core/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/dtype.h"

namespace hair::h5 {

namespace {

/// "/strands@unit" (root: "/@unit"): how errors name an attribute.
std::string attribute_location(const std::string& object_path, const std::string& name) {
  return object_path + "@" + name;
}

/// Creates (replacing an older one) and writes the attribute `name` of `object_path`.
void write_attribute(File& file, const std::string& object_path, const std::string& name,
                     hid_t stored_type, hid_t memory_type, hid_t space, const void* value) {
  const std::string location = attribute_location(object_path, name);
  if (file.kind_of(object_path) == ObjectKind::missing) {
    throw Error(ErrorKind::runtime, file.name(), location,
                "cannot write an attribute: no such object");
  }
  const Handle object = file.open_object(object_path);
  if (H5Aexists(object.get(), name.c_str()) > 0) H5Adelete(object.get(), name.c_str());
  const Handle attribute(
      H5Acreate2(object.get(), name.c_str(), stored_type, space, H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), memory_type, value) < 0) {
    throw Error(ErrorKind::runtime, file.name(), location,
                with_hdf5_message("cannot write attribute"));
  }
}

/// Opens the attribute `name` of `object_path`; bad_input if the object or attribute is missing.
Handle open_attribute(const File& file, const std::string& object_path, const std::string& name) {
  const Handle object = file.open_object(object_path);
  const htri_t exists = H5Aexists(object.get(), name.c_str());
  if (exists < 0) {
    throw Error::bad_dataset(file.name(), attribute_location(object_path, name),
                             with_hdf5_message("cannot read the file's metadata"));
  }
  if (exists == 0)
    throw Error::bad_dataset(file.name(), attribute_location(object_path, name),
                             "missing attribute");
  return Handle(H5Aopen(object.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
}

/// The extents of an attribute; empty for a scalar.
Shape attribute_shape(hid_t attribute) {
  const Handle space(H5Aget_space(attribute), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return Shape(dims.begin(), dims.end());
}

/// Opens an attribute and checks that it is of `dtype` and has rank `rank` (0: scalar).
Handle checked_attribute(const File& file, const std::string& object_path, const std::string& name,
                         Dtype dtype, size_t rank) {
  Handle attribute = open_attribute(file, object_path, name);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const std::string location = attribute_location(object_path, name);
  if (dtype_of_stored(type.get()) != dtype) {
    throw Error::bad_dataset(
        file.name(), location,
        "expected " + std::string(dtype_name(dtype)) + ", found " + stored_type_name(type.get()));
  }
  const Shape shape = attribute_shape(attribute.get());
  if (shape.size() != rank) {
    throw Error::bad_dataset(file.name(), location,
                             std::string("expected ") + (rank == 0 ? "a scalar" : "a 1-D array") +
                                 ", found shape " + format_shape(shape));
  }
  return attribute;
}

/// Shortest text that reads back as `value`.
std::string number_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

/// Reads all values of a numeric attribute converted to T (double or int64_t).
template <typename T>
std::vector<T> numeric_attribute_values(hid_t attribute) {
  const Handle space(H5Aget_space(attribute), H5Sclose);
  std::vector<T> values(static_cast<size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!values.empty()) H5Aread(attribute, memory_type(dtype_of<T>()), values.data());
  return values;
}

/// "[a, b, c]" for arrays, "a" for scalars.
template <typename T>
std::string numbers_text(const std::vector<T>& values, bool is_scalar) {
  std::string text;
  for (size_t index = 0; index < values.size(); ++index) {
    if (index > 0) text += ", ";
    if constexpr (std::is_same_v<T, double>)
      text += number_text(values[index]);
    else
      text += std::to_string(values[index]);
  }
  return is_scalar ? text : "[" + text + "]";
}

}  // namespace

void write_string_attribute(File& file, const std::string& object_path, const std::string& name,
                            const std::string& value) {
  // Fixed length, so that the text lives in the attribute's (checksummed) object header
  // or dense storage: a variable-length string goes through the global heap, which HDF5
  // does not checksum, and a corrupted one can crash the reader.
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<size_t>(value.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  std::string padded = value;
  padded.resize(std::max<size_t>(value.size(), 1), '\0');
  write_attribute(file, object_path, name, type.get(), type.get(), space.get(), padded.data());
}

void write_int64_attribute(File& file, const std::string& object_path, const std::string& name,
                           int64_t value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  write_attribute(file, object_path, name, file_type(Dtype::int64), memory_type(Dtype::int64),
                  space.get(), &value);
}

void write_double_attribute(File& file, const std::string& object_path, const std::string& name,
                            double value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  write_attribute(file, object_path, name, file_type(Dtype::float64), memory_type(Dtype::float64),
                  space.get(), &value);
}

void write_double_array_attribute(File& file, const std::string& object_path,
                                  const std::string& name, const std::vector<double>& values) {
  const hsize_t size = values.size();
  const Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose);
  write_attribute(file, object_path, name, file_type(Dtype::float64), memory_type(Dtype::float64),
                  space.get(), values.data());
}

bool has_attribute(const File& file, const std::string& object_path, const std::string& name) {
  if (file.kind_of(object_path) == ObjectKind::missing) return false;
  const Handle object = file.open_object(object_path);
  const htri_t exists = H5Aexists(object.get(), name.c_str());
  if (exists < 0) {
    // Not absent: HDF5 could not read the object's attributes (a checksum failed, say).
    throw Error::bad_dataset(file.name(), attribute_location(object_path, name),
                             with_hdf5_message("cannot read the file's metadata"));
  }
  return exists > 0;
}

std::string read_string_attribute(const File& file, const std::string& object_path,
                                  const std::string& name) {
  const Handle attribute = open_attribute(file, object_path, name);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const std::string location = attribute_location(object_path, name);
  if (H5Tget_class(type.get()) != H5T_STRING) {
    throw Error::bad_dataset(file.name(), location,
                             "expected string, found " + stored_type_name(type.get()));
  }
  if (!attribute_shape(attribute.get()).empty()) {
    throw Error::bad_dataset(file.name(), location, "expected a scalar string, found an array");
  }
  const Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
  if (H5Tis_variable_str(type.get()) > 0) {
    H5Tset_size(memory.get(), H5T_VARIABLE);
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0) {
      throw Error::bad_dataset(file.name(), location, with_hdf5_message("cannot read attribute"));
    }
    std::string value = text != nullptr ? text : "";
    H5free_memory(text);
    return value;
  }
  const size_t size = H5Tget_size(type.get());
  H5Tset_size(memory.get(), size + 1);
  H5Tset_strpad(memory.get(), H5T_STR_NULLTERM);
  std::string buffer(size + 1, '\0');
  if (H5Aread(attribute.get(), memory.get(), buffer.data()) < 0) {
    throw Error::bad_dataset(file.name(), location, with_hdf5_message("cannot read attribute"));
  }
  return buffer.substr(0, buffer.find('\0'));
}

int64_t read_int64_attribute(const File& file, const std::string& object_path,
                             const std::string& name) {
  const Handle attribute = checked_attribute(file, object_path, name, Dtype::int64, 0);
  int64_t value = 0;
  H5Aread(attribute.get(), memory_type(Dtype::int64), &value);
  return value;
}

double read_double_attribute(const File& file, const std::string& object_path,
                             const std::string& name) {
  const Handle attribute = checked_attribute(file, object_path, name, Dtype::float64, 0);
  double value = 0;
  H5Aread(attribute.get(), memory_type(Dtype::float64), &value);
  return value;
}

std::vector<double> read_double_array_attribute(const File& file, const std::string& object_path,
                                                const std::string& name) {
  const Handle attribute = checked_attribute(file, object_path, name, Dtype::float64, 1);
  return numeric_attribute_values<double>(attribute.get());
}

std::vector<std::string> attribute_names(const File& file, const std::string& object_path) {
  const Handle object = file.open_object(object_path);
  std::vector<std::string> names;
  hsize_t index = 0;
  H5Aiterate2(
      object.get(), H5_INDEX_NAME, H5_ITER_INC, &index,
      [](hid_t, const char* attribute_name, const H5A_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(attribute_name);
        return 0;
      },
      &names);
  return names;
}

std::string attribute_type_name(const File& file, const std::string& object_path,
                                const std::string& name) {
  const Handle attribute = open_attribute(file, object_path, name);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const Shape shape = attribute_shape(attribute.get());
  return stored_type_name(type.get()) + (shape.empty() ? "" : format_shape(shape));
}

std::string attribute_text(const File& file, const std::string& object_path,
                           const std::string& name) {
  const Handle attribute = open_attribute(file, object_path, name);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const bool is_scalar = attribute_shape(attribute.get()).empty();
  switch (H5Tget_class(type.get())) {
    case H5T_STRING:
      if (is_scalar) return read_string_attribute(file, object_path, name);
      break;
    case H5T_INTEGER:
      return numbers_text(numeric_attribute_values<int64_t>(attribute.get()), is_scalar);
    case H5T_FLOAT:
      return numbers_text(numeric_attribute_values<double>(attribute.get()), is_scalar);
    default:
      break;
  }
  return fmt::format("<{}>", attribute_type_name(file, object_path, name));
}

}  // namespace hair::h5
