#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hair/core/error.h"
#include "hair/h5/handle.h"

namespace hair::h5 {

/// The first superblock version whose metadata HDF5 checksums (HDF5 1.8 and later formats).
inline constexpr unsigned kChecksummedSuperblockVersion = 2;
/// The superblock version of the files File::create writes (the HDF5 1.10 format).
inline constexpr unsigned kWrittenSuperblockVersion = 3;

/// What an absolute path inside a file names.
enum class ObjectKind { missing, group, dataset, other };

/// An open HDF5 file. Paths inside it are absolute ("/strands/points"); "/" is the root
/// group. Every failure throws hair::Error naming the file and the object: problems
/// with a file's content are bad_input, failures to write are runtime errors. HDF5's
/// own error printing is off.
class File {
 public:
  /// Creates (or truncates) `path` for writing. `display_name` is the name errors use
  /// (e.g. the final name of an output written under a temporary name); by default the
  /// path itself. The file is written in the HDF5 1.10 format, whose metadata is
  /// checksummed (has_checksummed_metadata()).
  static File create(const std::filesystem::path& path, std::string display_name = {});

  /// Opens an existing HDF5 file read-only. A missing file, one that is not HDF5, and one
  /// whose metadata is not checksummed throughout (unchecked_metadata()) is a bad_input
  /// error: libhdf5 follows unchecked metadata as it finds it, and corrupted, it can
  /// crash the reader.
  static File open_read_only(const std::filesystem::path& path, std::string display_name = {});

  File(File&& other) noexcept = default;
  File& operator=(File&& other) noexcept = default;
  ~File() = default;

  /// The name errors use for this file.
  const std::string& name() const { return name_; }

  /// The HDF5 file identifier, for the functions of hair/h5 that read and write.
  hid_t id() const { return file_.get(); }

  bool writable() const { return writable_; }

  /// True if the file's metadata carries checksums (superblock version 2 or later, as
  /// File::create writes): HDF5 then refuses corrupted metadata instead of following it.
  bool has_checksummed_metadata() const;

  /// Why HDF5 would follow some of this file's metadata unchecked (a bad_input error
  /// naming the file and the object), or nothing: a
  /// superblock before version 2, or an object keeping its links or attributes in
  /// "dense" storage (fractal heaps, whose blocks have no checksum), which hairstyle
  /// never writes (kMaxCompactMembers). open_read_only() refuses such a file.
  std::optional<Error> unchecked_metadata() const;

  /// What `path` names; missing intermediate groups give ObjectKind::missing. Metadata that
  /// HDF5 cannot read on the way (a failed checksum) is a bad_input error naming the object.
  ObjectKind kind_of(const std::string& path) const;

  /// True if `path` names a group, dataset or other object.
  bool exists(const std::string& path) const { return kind_of(path) != ObjectKind::missing; }

  /// Names of the members (groups, datasets, links) of the group `path`, in name order.
  std::vector<std::string> member_names(const std::string& path) const;

  /// Creates the group `path` and any missing intermediate groups; an existing group is
  /// kept. A dataset in the way is a runtime error.
  void create_group(const std::string& path);

  /// Opens the dataset `path`; throws bad_input naming it if it is missing or not a
  /// dataset.
  Handle open_dataset(const std::string& path) const;

  /// Opens the group or dataset `path` (to read or write its attributes); throws
  /// bad_input if it is missing.
  Handle open_object(const std::string& path) const;

  /// Writes what HDF5 holds in memory to the file (a file opened to write); throws a
  /// runtime error if it cannot ("no space left on device" where the disk is full).
  /// HDF5 keeps small datasets and metadata in memory until then, so a write into a full
  /// file system fails here, not where the dataset was written.
  void flush() const;

  /// Flushes and closes the file, throwing a runtime error if HDF5 cannot; call before
  /// committing an output. Further use of the File is an error.
  void close();

 private:
  File(Handle file, std::string name, bool writable)
      : file_(std::move(file)), name_(std::move(name)), writable_(writable) {}

  Handle file_;
  std::string name_;
  bool writable_ = false;
};

/// Most links or attributes an object keeps in its own header ("compact" storage). HDF5
/// moves more than 8 (its default) into "dense" storage, a fractal heap whose blocks carry
/// no checksum, where a corrupted link crashed libhdf5 (H5G__dense_iterate) under the
/// fuzzer; object headers are checksummed. hairstyle's groups hold tens of members.
inline constexpr unsigned kMaxCompactMembers = 65535;

/// Sets object creation properties (of a file's root group, a group or a dataset) so
/// that the object keeps its attributes, and with `has_links` its links, in its header
/// (kMaxCompactMembers).
void keep_in_object_header(hid_t creation_properties, bool has_links);

/// Group creation properties that leave out modification times, so that equal content
/// gives byte-identical files, and keep links and attributes in the checksummed header
/// (keep_in_object_header()). Used for every group hairstyle creates.
Handle untimed_group_properties();

/// The path of member `name` of the group `group_path`: ("/a", "b") -> "/a/b", ("/", "b") -> "/b".
std::string child_path(const std::string& group_path, const std::string& name);

/// The parent group of an absolute path: "/a/b" -> "/a", "/a" -> "/".
std::string parent_path(const std::string& path);

}  // namespace hair::h5
