#include "hair/h5/handle.h"

#include <mutex>
#include <utility>

namespace hair::h5 {

Handle::Handle(Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    close();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

Handle::~Handle() { close(); }

bool Handle::close() {
  if (id_ < 0) return true;
  const herr_t status = closer_(id_);
  id_ = H5I_INVALID_HID;
  return status >= 0;
}

void silence_hdf5_error_printing() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Every file is closed by its owner. HDF5's own clean-up at exit would close again a
    // file whose flush failed (a full disk), and crashes in HDF5 1.10 doing so.
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

namespace {

/// H5Ewalk2 callback: keeps the description of the first (innermost) entry.
herr_t keep_innermost_message(unsigned index, const H5E_error2_t* entry, void* message) {
  if (index == 0 && entry->desc != nullptr) *static_cast<std::string*>(message) = entry->desc;
  return 0;
}

}  // namespace

std::string with_hdf5_message(std::string reason) {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost_message, &message);
  H5Eclear2(H5E_DEFAULT);
  if (!message.empty()) reason += " (" + message + ")";
  return reason;
}

}  // namespace hair::h5
