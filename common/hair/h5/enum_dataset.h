#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hair/h5/dataset.h"
#include "hair/h5/file.h"

namespace hair::h5 {

/// One name of an enumeration and its stored value.
struct EnumMember {
  std::string name;  ///< the word used in the paper, e.g. "root_free"
  int8_t value;
  bool operator==(const EnumMember&) const = default;
};

/// The members of an HDF5 enum type over int8, in the order they were declared.
using EnumMembers = std::vector<EnumMember>;

/// "{strip=0, grid=1}".
std::string format_enum_members(const EnumMembers& members);

/// The stored values of enum class values (over int8), as write_enum_dataset() takes them.
template <class Enum>
std::vector<int8_t> enum_values(const std::vector<Enum>& values) {
  std::vector<int8_t> raw;
  raw.reserve(values.size());
  for (Enum value : values) raw.push_back(static_cast<int8_t>(value));
  return raw;
}

/// Writes `values` (one per element, each the value of a member) as the 1-D dataset
/// `path` of an HDF5 enum type over int8 with `members`. A value that is no member, or
/// members with repeated names or values, are a runtime error.
void write_enum_dataset(File& file, const std::string& path, const std::vector<int8_t>& values,
                        const EnumMembers& members, const DatasetOptions& options = {});

/// The members of the enum type of dataset `path`, sorted by value; bad_input if the
/// dataset is missing or not an enum over int8.
EnumMembers read_enum_members(const File& file, const std::string& path);

/// The stored values of the enum dataset `path` (any rank, row-major), without
/// checking its members; bad_input if it is not an enum over int8.
std::vector<int8_t> read_enum_values(const File& file, const std::string& path);

/// Reads the 1-D enum dataset `path`, checking that its members are exactly `expected`
/// (same names with the same values, in any order) and that every value is a member.
/// A difference is a bad_input error naming it ("member 'fan' missing").
std::vector<int8_t> read_enum_dataset(const File& file, const std::string& path,
                                      const EnumMembers& expected);

/// The first difference between the members of a file's enum and the expected ones
/// ("member 'tube' has value 3, expected 2"), or an empty string if they agree.
std::string enum_members_difference(const EnumMembers& found, const EnumMembers& expected);

}  // namespace hair::h5
