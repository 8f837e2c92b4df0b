#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hair/h5/file.h"

namespace hair::h5 {

// Attributes of a group or dataset named by its absolute path ("/" for the root).
// Writing replaces an attribute of the same name. Reading checks the stored type and
// throws bad_input naming the object and attribute ("/@schema_version: expected int64,
// found float64"); a missing attribute is a bad_input error too.

/// A scalar UTF-8 string, stored fixed-length (null-padded) so that it stays in checksummed
/// metadata. Readers take fixed- and variable-length strings alike.
void write_string_attribute(File& file, const std::string& object_path, const std::string& name,
                            const std::string& value);

/// A scalar int64.
void write_int64_attribute(File& file, const std::string& object_path, const std::string& name,
                           int64_t value);

/// A scalar float64.
void write_double_attribute(File& file, const std::string& object_path, const std::string& name,
                            double value);

/// A 1-D float64 array of #values elements.
void write_double_array_attribute(File& file, const std::string& object_path,
                                  const std::string& name, const std::vector<double>& values);

/// True if the object `object_path` exists and has an attribute `name`.
bool has_attribute(const File& file, const std::string& object_path, const std::string& name);

/// Reads a scalar string attribute (variable- or fixed-length, as h5py may write either).
std::string read_string_attribute(const File& file, const std::string& object_path,
                                  const std::string& name);

/// Reads a scalar int64 attribute.
int64_t read_int64_attribute(const File& file, const std::string& object_path,
                             const std::string& name);

/// Reads a scalar float64 attribute.
double read_double_attribute(const File& file, const std::string& object_path,
                             const std::string& name);

/// Reads a 1-D float64 array attribute.
std::vector<double> read_double_array_attribute(const File& file, const std::string& object_path,
                                                const std::string& name);

/// Names of the attributes of `object_path`, in alphabetical order.
std::vector<std::string> attribute_names(const File& file, const std::string& object_path);

/// The stored type of an attribute as stored_type_name() gives it ("string", "int64", ...),
/// followed by its shape if it is not scalar ("float64[3]").
std::string attribute_type_name(const File& file, const std::string& object_path,
                                const std::string& name);

/// The value of any attribute as text: strings as they are, numbers in full precision,
/// arrays as "[1, 2, 3]"; other types as "<type>".
std::string attribute_text(const File& file, const std::string& object_path,
                           const std::string& name);

}  // namespace hair::h5
