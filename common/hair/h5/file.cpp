#include "hair/h5/file.h"

#include <optional>
#include <set>
#include <system_error>
#include <utility>
#include <vector>

#include "hair/core/error.h"

namespace hair::h5 {

namespace {

/// The components of an absolute path: "/a/b" -> {"a", "b"}; "/" -> {}.
std::vector<std::string> path_components(const std::string& path) {
  std::vector<std::string> components;
  size_t begin = 0;
  while (begin < path.size()) {
    size_t end = path.find('/', begin);
    if (end == std::string::npos) end = path.size();
    if (end > begin) components.push_back(path.substr(begin, end - begin));
    begin = end + 1;
  }
  return components;
}

/// File access properties: closing the file closes every object still open in it.
Handle strong_close_access() {
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG);
  return access;
}

/// Access properties for files hairstyle writes: strong close, and the HDF5 1.10 file
/// format at both bounds, whatever library builds it. That format checksums all of the
/// file's metadata (superblock version 3, object headers version 2, fixed and extensible
/// arrays, version 2 B-trees, fractal heaps), so a flipped byte in it is a read error
/// rather than a wild pointer; and pinning the upper bound keeps files byte-identical
/// across library versions.
Handle checksummed_format_access() {
  Handle access = strong_close_access();
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_V110, H5F_LIBVER_V110);
  return access;
}

}  // namespace

std::string child_path(const std::string& group_path, const std::string& name) {
  return (group_path.ends_with('/') ? group_path : group_path + "/") + name;
}

std::string parent_path(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos || slash == 0) return "/";
  return path.substr(0, slash);
}

void keep_in_object_header(hid_t creation_properties, bool has_links) {
  H5Pset_attr_phase_change(creation_properties, kMaxCompactMembers, kMaxCompactMembers);
  if (has_links)
    H5Pset_link_phase_change(creation_properties, kMaxCompactMembers, kMaxCompactMembers);
}

Handle untimed_group_properties() {
  Handle properties(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_obj_track_times(properties.get(), false);
  keep_in_object_header(properties.get(), true);
  return properties;
}

File File::create(const std::filesystem::path& path, std::string display_name) {
  silence_hdf5_error_printing();
  if (display_name.empty()) display_name = path.string();
  const Handle access = checksummed_format_access();
  // The root group's header leaves out times too (in this format it would keep them),
  // and keeps its links and attributes in itself, as every group does.
  const Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  H5Pset_obj_track_times(creation.get(), false);
  keep_in_object_header(creation.get(), true);
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()), H5Fclose);
  if (!file.valid()) {
    throw Error::runtime(display_name, with_hdf5_message("cannot create HDF5 file"));
  }
  return File(std::move(file), std::move(display_name), true);
}

File File::open_read_only(const std::filesystem::path& path, std::string display_name) {
  silence_hdf5_error_printing();
  if (display_name.empty()) display_name = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw Error::bad_input(display_name, "no such file");
  if (!std::filesystem::is_regular_file(path, error)) {
    throw Error::bad_input(display_name, "not a regular file");
  }
  const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
  if (is_hdf5 == 0) throw Error::bad_input(display_name, "not an HDF5 file");
  const Handle access = strong_close_access();
  Handle file(is_hdf5 > 0 ? H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()) : -1, H5Fclose);
  if (!file.valid()) {
    throw Error::bad_input(display_name, with_hdf5_message("cannot open HDF5 file"));
  }
  File opened(std::move(file), std::move(display_name), false);
  if (std::optional<Error> unchecked = opened.unchecked_metadata()) throw std::move(*unchecked);
  return opened;
}

bool File::has_checksummed_metadata() const {
  H5F_info2_t info{};
  if (H5Fget_info2(id(), &info) < 0) {
    H5Eclear2(H5E_DEFAULT);
    return false;
  }
  return info.super.version >= kChecksummedSuperblockVersion;
}

namespace {

/// The error for metadata HDF5 cannot read at `where` (a checksum failed, say).
Error unreadable_metadata(const std::string& file, const std::string& where) {
  return Error::bad_dataset(file, where, with_hdf5_message("cannot read the file's metadata"));
}

/// Members of the group `group` that are groups or datasets (hard links only: soft and
/// external links are not followed), as paths; nothing if HDF5 cannot list them.
std::optional<std::vector<std::string>> hard_link_members(hid_t file, const std::string& group) {
  std::vector<std::string> names;
  hsize_t index = 0;
  if (H5Literate_by_name(
          file, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, &index,
          [](hid_t, const char* name, const H5L_info_t* info, void* data) -> herr_t {
            if (info->type == H5L_TYPE_HARD)
              static_cast<std::vector<std::string>*>(data)->push_back(name);
            return 0;
          },
          &names, H5P_DEFAULT) < 0)
    return std::nullopt;
  for (std::string& name : names) name = child_path(group, name);
  return names;
}

}  // namespace

std::optional<Error> File::unchecked_metadata() const {
  H5F_info2_t file_info{};
  if (H5Fget_info2(id(), &file_info) < 0) return unreadable_metadata(name_, "/");
  if (file_info.super.version < kChecksummedSuperblockVersion) {
    return Error::bad_input(
        name_, "written without metadata checksums (HDF5 superblock version " +
                   std::to_string(file_info.super.version) + "; hairstyle writes version " +
                   std::to_string(kWrittenSuperblockVersion) +
                   "), not by this hairstyle: rerun the stage that wrote it");
  }
  // Every object's links and attributes in its own (checksummed) header, as hairstyle
  // writes them: "dense" storage keeps them in fractal heap blocks without checksums.
  // Each group's storage is read from its header before its links are listed, so
  // nothing unchecked is followed on the way.
  // Each object once, by its address: a hard link back to a group above would loop.
  std::vector<std::string> pending = {"/"};
  std::set<haddr_t> seen;
  while (!pending.empty()) {
    const std::string path = pending.back();
    pending.pop_back();
    H5O_info_t info{};
    if (H5Oget_info_by_name2(id(), path.c_str(), &info, H5O_INFO_BASIC | H5O_INFO_META_SIZE,
                             H5P_DEFAULT) < 0)
      return unreadable_metadata(name_, path);
    if (!seen.insert(info.addr).second) continue;
    const std::string unchecked =
        ", which HDF5 does not checksum (not written by this hairstyle): rerun the stage "
        "that wrote it";
    if (info.meta_size.attr.heap_size > 0)
      return Error::bad_dataset(name_, path, "attributes in dense storage" + unchecked);
    if (info.type != H5O_TYPE_GROUP) continue;
    H5G_info_t group{};
    if (H5Gget_info_by_name(id(), path.c_str(), &group, H5P_DEFAULT) < 0)
      return unreadable_metadata(name_, path);
    if (group.storage_type != H5G_STORAGE_TYPE_COMPACT && group.nlinks > 0)
      return Error::bad_dataset(name_, path, "links in dense storage" + unchecked);
    const std::optional<std::vector<std::string>> members = hard_link_members(id(), path);
    if (!members) return unreadable_metadata(name_, path);
    pending.insert(pending.end(), members->begin(), members->end());
  }
  return std::nullopt;
}

ObjectKind File::kind_of(const std::string& path) const {
  // Component by component, so that a missing group on the way reads as missing. Where
  // HDF5 fails to read a group's links or an object's header (a checksum failed, say),
  // the file is corrupt: that is an error, not a missing object.
  const std::vector<std::string> components = path_components(path);
  std::string prefix;
  ObjectKind kind = ObjectKind::group;  // the root
  for (const std::string& component : components) {
    if (kind != ObjectKind::group) return ObjectKind::missing;  // a path through a dataset
    prefix += "/" + component;
    const htri_t exists = H5Lexists(id(), prefix.c_str(), H5P_DEFAULT);
    if (exists < 0) throw unreadable_metadata(name_, prefix);
    if (exists == 0) return ObjectKind::missing;
    const Handle object(H5Oopen(id(), prefix.c_str(), H5P_DEFAULT), H5Oclose);
    if (!object.valid()) throw unreadable_metadata(name_, prefix);
    switch (H5Iget_type(object.get())) {
      case H5I_GROUP:
        kind = ObjectKind::group;
        break;
      case H5I_DATASET:
        kind = ObjectKind::dataset;
        break;
      default:
        kind = ObjectKind::other;
    }
  }
  if (components.empty()) {
    const Handle root(H5Oopen(id(), "/", H5P_DEFAULT), H5Oclose);
    if (!root.valid()) throw unreadable_metadata(name_, "/");
  }
  return kind;
}

std::vector<std::string> File::member_names(const std::string& path) const {
  if (kind_of(path) != ObjectKind::group) throw Error::bad_dataset(name_, path, "missing group");
  const Handle group(H5Gopen2(id(), path.c_str(), H5P_DEFAULT), H5Gclose);
  std::vector<std::string> names;
  hsize_t index = 0;
  H5Literate(
      group.get(), H5_INDEX_NAME, H5_ITER_INC, &index,
      [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
      },
      &names);
  return names;
}

void File::create_group(const std::string& path) {
  const Handle properties = untimed_group_properties();
  std::string prefix;
  for (const std::string& component : path_components(path)) {
    prefix += "/" + component;
    const ObjectKind kind = kind_of(prefix);
    if (kind == ObjectKind::group) continue;
    if (kind != ObjectKind::missing) {
      throw Error(ErrorKind::runtime, name_, prefix,
                  "cannot create a group: another object is there");
    }
    const Handle group(H5Gcreate2(id(), prefix.c_str(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                       H5Gclose);
    if (!group.valid()) {
      throw Error(ErrorKind::runtime, name_, prefix, with_hdf5_message("cannot create group"));
    }
  }
}

Handle File::open_dataset(const std::string& path) const {
  const ObjectKind kind = kind_of(path);
  if (kind == ObjectKind::missing) throw Error::bad_dataset(name_, path, "missing dataset");
  if (kind != ObjectKind::dataset) {
    throw Error::bad_dataset(name_, path,
                             kind == ObjectKind::group
                                 ? "expected a dataset, found a group"
                                 : "expected a dataset, found another object");
  }
  Handle dataset(H5Dopen2(id(), path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) {
    throw Error::bad_dataset(name_, path, with_hdf5_message("cannot open dataset"));
  }
  return dataset;
}

Handle File::open_object(const std::string& path) const {
  if (kind_of(path) == ObjectKind::missing) throw Error::bad_dataset(name_, path, "missing object");
  Handle object(H5Oopen(id(), path.c_str(), H5P_DEFAULT), H5Oclose);
  if (!object.valid()) {
    throw Error::bad_dataset(name_, path, with_hdf5_message("cannot open object"));
  }
  return object;
}

void File::flush() const {
  if (!writable_ || !file_.valid() || H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) >= 0) return;
  const std::string message = with_hdf5_message("cannot write HDF5 file");
  if (message.find("No space left on device") != std::string::npos)
    throw Error::runtime(name_, "cannot write HDF5 file: no space left on device");
  throw Error::runtime(name_, message);
}

void File::close() {
  if (!file_.valid()) return;
  flush();
  if (!file_.close()) throw Error::runtime(name_, with_hdf5_message("cannot close HDF5 file"));
}

}  // namespace hair::h5
