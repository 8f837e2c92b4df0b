#include "hair/h5/enum_dataset.h"

#include <algorithm>
#include <set>

#include "hair/core/error.h"

namespace hair::h5 {

namespace {

/// The HDF5 enum type over int8 with `members`; a runtime error if names or values repeat.
Handle enum_type(const EnumMembers& members, const std::string& file_name,
                 const std::string& path) {
  std::set<std::string> names;
  std::set<int8_t> values;
  Handle type(H5Tenum_create(H5T_STD_I8LE), H5Tclose);
  for (const EnumMember& member : members) {
    if (!names.insert(member.name).second || !values.insert(member.value).second) {
      throw Error(ErrorKind::runtime, file_name, path,
                  "enum members repeat a name or value: " + format_enum_members(members));
    }
    H5Tenum_insert(type.get(), member.name.c_str(), &member.value);
  }
  return type;
}

/// The enum type of an open dataset, or a bad_input error if it is no enum over int8.
Handle checked_enum_type(hid_t dataset, const File& file, const std::string& path) {
  Handle type(H5Dget_type(dataset), H5Tclose);
  const std::string type_name = stored_type_name(type.get());
  if (type_name != "enum int8") {
    throw Error::bad_dataset(file.name(), path, "expected enum int8, found " + type_name);
  }
  return type;
}

const EnumMember* member_named(const EnumMembers& members, const std::string& name) {
  const auto found = std::find_if(members.begin(), members.end(),
                                  [&](const EnumMember& member) { return member.name == name; });
  return found == members.end() ? nullptr : &*found;
}

}  // namespace

std::string format_enum_members(const EnumMembers& members) {
  std::string text = "{";
  for (size_t index = 0; index < members.size(); ++index) {
    if (index > 0) text += ", ";
    text += members[index].name + "=" + std::to_string(members[index].value);
  }
  return text + "}";
}

void write_enum_dataset(File& file, const std::string& path, const std::vector<int8_t>& values,
                        const EnumMembers& members, const DatasetOptions& options) {
  const Handle type = enum_type(members, file.name(), path);
  for (size_t index = 0; index < values.size(); ++index) {
    const bool is_member = std::any_of(members.begin(), members.end(), [&](const EnumMember& m) {
      return m.value == values[index];
    });
    if (!is_member) {
      throw Error(ErrorKind::runtime, file.name(), path,
                  "value " + std::to_string(values[index]) + " at [" + std::to_string(index) +
                      "] is no member of " + format_enum_members(members));
    }
  }
  write_raw_dataset(file, path, type.get(), type.get(), values.data(),
                    {static_cast<int64_t>(values.size())}, options);
}

EnumMembers read_enum_members(const File& file, const std::string& path) {
  const Handle dataset = file.open_dataset(path);
  const Handle type = checked_enum_type(dataset.get(), file, path);
  EnumMembers members;
  const int count = H5Tget_nmembers(type.get());
  for (int index = 0; index < count; ++index) {
    char* name = H5Tget_member_name(type.get(), static_cast<unsigned>(index));
    int8_t value = 0;
    H5Tget_member_value(type.get(), static_cast<unsigned>(index), &value);
    members.push_back({name != nullptr ? name : "", value});
    H5free_memory(name);
  }
  std::sort(members.begin(), members.end(),
            [](const EnumMember& a, const EnumMember& b) { return a.value < b.value; });
  return members;
}

std::vector<int8_t> read_enum_values(const File& file, const std::string& path) {
  const Handle dataset = file.open_dataset(path);
  const Handle type = checked_enum_type(dataset.get(), file, path);
  const Handle space(H5Dget_space(dataset.get()), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  std::vector<int8_t> values(static_cast<size_t>(std::max<hssize_t>(count, 0)));
  if (!values.empty() &&
      H5Dread(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw Error::bad_dataset(file.name(), path, with_hdf5_message("cannot read dataset"));
  }
  return values;
}

std::string enum_members_difference(const EnumMembers& found, const EnumMembers& expected) {
  for (const EnumMember& member : expected) {
    const EnumMember* match = member_named(found, member.name);
    if (match == nullptr) return "enum member '" + member.name + "' missing";
    if (match->value != member.value) {
      return "enum member '" + member.name + "' has value " + std::to_string(match->value) +
             ", expected " + std::to_string(member.value);
    }
  }
  for (const EnumMember& member : found) {
    if (member_named(expected, member.name) == nullptr) {
      return "unexpected enum member '" + member.name + "'";
    }
  }
  return {};
}

std::vector<int8_t> read_enum_dataset(const File& file, const std::string& path,
                                      const EnumMembers& expected) {
  const std::string difference = enum_members_difference(read_enum_members(file, path), expected);
  if (!difference.empty()) {
    throw Error::bad_dataset(file.name(), path,
                             difference + " (expected " + format_enum_members(expected) + ")");
  }
  const DatasetInfo info = dataset_info(file, path);
  if (info.shape.size() != 1) {
    throw Error::bad_dataset(file.name(), path,
                             "expected shape [n], found " + format_shape(info.shape));
  }
  std::vector<int8_t> values = read_enum_values(file, path);
  for (size_t index = 0; index < values.size(); ++index) {
    const bool is_member = std::any_of(expected.begin(), expected.end(), [&](const EnumMember& m) {
      return m.value == values[index];
    });
    if (!is_member) {
      throw Error::bad_dataset(file.name(), path,
                               "expected a member of " + format_enum_members(expected) +
                                   ", found value " + std::to_string(values[index]) + " at [" +
                                   std::to_string(index) + "]");
    }
  }
  return values;
}

}  // namespace hair::h5
