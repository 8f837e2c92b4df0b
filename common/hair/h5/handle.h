#pragma once

#include <hdf5.h>

#include <string>

namespace hair::h5 {

/// Owns one HDF5 identifier (file, group, dataset, dataspace, datatype, attribute or
/// property list) and closes it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept;
  Handle& operator=(Handle&& other) noexcept;
  ~Handle();

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

  /// Closes the identifier now; returns false if HDF5 reported a failure.
  bool close();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// Turns off HDF5's automatic printing of its error stack, and its clean-up at exit (once
/// per process, before any other HDF5 call); every failure is reported through
/// hair::Error instead, and every file is closed by its owner.
void silence_hdf5_error_printing();

/// `reason` followed by the innermost message of HDF5's error stack in parentheses
/// (e.g. "cannot open dataset (unable to open file)"), or just `reason` if the stack is
/// empty; clears the stack.
std::string with_hdf5_message(std::string reason);

}  // namespace hair::h5
