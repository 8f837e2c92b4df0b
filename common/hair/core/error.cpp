#include "hair/core/error.h"

#include <algorithm>
#include <utility>

namespace hair {

std::string error_line(const std::string& file, const std::string& dataset,
                       const std::string& reason) {
  std::string line = file;
  if (!dataset.empty()) {
    if (!line.empty()) line.push_back(':');
    line.append(dataset);
  }
  if (!line.empty()) line.append(": ");
  line.append(reason);
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  return line;
}

Error::Error(ErrorKind kind, std::string file, std::string dataset, std::string reason)
    : std::runtime_error(error_line(file, dataset, reason)),
      kind_(kind),
      file_(std::move(file)),
      dataset_(std::move(dataset)),
      reason_(std::move(reason)) {}

Error Error::bad_input(std::string file, std::string reason) {
  return Error(ErrorKind::bad_input, std::move(file), {}, std::move(reason));
}

Error Error::bad_dataset(std::string file, std::string dataset, std::string reason) {
  return Error(ErrorKind::bad_input, std::move(file), std::move(dataset), std::move(reason));
}

Error Error::other_model(std::string file, std::string dataset, size_t count,
                         const std::string& what, const std::string& other, size_t other_count) {
  return bad_dataset(std::move(file), std::move(dataset),
                     "has " + std::to_string(count) + " " + what + ", " + other + " " +
                         std::to_string(other_count) + ": made from another model");
}

Error Error::usage(std::string reason) {
  return Error(ErrorKind::usage, {}, {}, std::move(reason));
}

Error Error::runtime(std::string file, std::string reason) {
  return Error(ErrorKind::runtime, std::move(file), {}, std::move(reason));
}

int Error::exit_code() const { return kind_ == ErrorKind::runtime ? 1 : 2; }

}  // namespace hair
