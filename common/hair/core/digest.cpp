#include "hair/core/digest.h"

#include <openssl/evp.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "hair/core/error.h"

namespace hair {

struct Sha256::Context {
  EVP_MD_CTX* evp = nullptr;
};

Sha256::Sha256() : context_(std::make_unique<Context>()) {
  context_->evp = EVP_MD_CTX_new();
  if (context_->evp == nullptr || EVP_DigestInit_ex(context_->evp, EVP_sha256(), nullptr) != 1) {
    EVP_MD_CTX_free(context_->evp);
    throw Error::runtime("", "cannot start a SHA-256 digest (OpenSSL)");
  }
}

Sha256::~Sha256() { EVP_MD_CTX_free(context_->evp); }

void Sha256::update(std::span<const std::byte> bytes) {
  if (EVP_DigestUpdate(context_->evp, bytes.data(), bytes.size()) != 1) {
    throw Error::runtime("", "SHA-256 digest failed (OpenSSL)");
  }
}

std::string Sha256::hex_digest() {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context_->evp, digest, &length) != 1) {
    throw Error::runtime("", "SHA-256 digest failed (OpenSSL)");
  }
  static constexpr char kHexDigits[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int index = 0; index < length; ++index) {
    hex += kHexDigits[digest[index] >> 4];
    hex += kHexDigits[digest[index] & 0x0f];
  }
  return hex;
}

std::string sha256_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw Error::bad_input(path.string(), std::filesystem::exists(path, error)
                                              ? "cannot digest: not a regular file"
                                              : "cannot digest: no such file");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) {
    throw Error::bad_input(path.string(), std::string("cannot read: ") + std::strerror(errno));
  }
  constexpr size_t kBlockBytes = size_t{1} << 20;
  std::vector<char> block(kBlockBytes);
  Sha256 digest;
  while (stream) {
    stream.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::streamsize count = stream.gcount();
    if (count > 0)
      digest.update(std::as_bytes(std::span(block.data(), static_cast<size_t>(count))));
  }
  if (stream.bad()) throw Error::bad_input(path.string(), "read error while digesting");
  return digest.hex_digest();
}

}  // namespace hair
