#pragma once

#include <stdexcept>
#include <string>

namespace hair {

/// What went wrong decides the exit status of a stage (DESIGN.md, contract 1).
enum class ErrorKind {
  bad_input,  ///< a file, mesh, schema or value the user gave is unusable: exit 2
  usage,      ///< the command line or a parameter is wrong: exit 2
  runtime,    ///< the input was fine but the work failed (I/O, numerics): exit 1
};

/// The one error type of libhair. It carries the file, the dataset inside the
/// file (may be empty) and the reason, and renders them as one line:
///   "strands.h5:/points: expected [n,3] float32, found [n,4] float64"
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string file, std::string dataset, std::string reason);

  static Error bad_input(std::string file, std::string reason);
  static Error bad_dataset(std::string file, std::string dataset, std::string reason);
  static Error usage(std::string reason);
  static Error runtime(std::string file, std::string reason);
  /// Files of two models given together: "<file>:<dataset>: has <count> <what>, <other>
  /// <other_count>: made from another model".
  static Error other_model(std::string file, std::string dataset, size_t count,
                           const std::string& what, const std::string& other, size_t other_count);

  ErrorKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  const std::string& dataset() const { return dataset_; }
  const std::string& reason() const { return reason_; }

  /// 2 for bad input or usage, 1 for a runtime failure.
  int exit_code() const;

 private:
  ErrorKind kind_;
  std::string file_;
  std::string dataset_;
  std::string reason_;
};

/// Formats file, dataset and reason as one line (newlines become spaces).
std::string error_line(const std::string& file, const std::string& dataset,
                       const std::string& reason);

}  // namespace hair
