#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace hair {

/// Incremental SHA-256 (OpenSSL EVP).
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  /// Adds bytes to the message.
  void update(std::span<const std::byte> bytes);

  /// The digest of everything added, as 64 lowercase hex digits; ends the computation.
  std::string hex_digest();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

/// SHA-256 of a file's content as 64 lowercase hex digits, read in 1 MiB blocks. A
/// missing or unreadable file is a bad_input error naming it.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace hair
