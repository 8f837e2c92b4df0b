#include <fstream>

#include "hair/core/digest.h"
#include "hair/core/error.h"
#include "unit/test_h5_support.h"

namespace hair {
namespace {

using DigestTest = testing::TemporaryDirectoryTest;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST_F(DigestTest, KnownVectors) {
  write_text(path("abc.txt"), "abc");
  EXPECT_EQ(sha256_file(path("abc.txt")),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  write_text(path("empty.txt"), "");
  EXPECT_EQ(sha256_file(path("empty.txt")),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  write_text(path("million.txt"), std::string(1'000'000, 'a'));
  EXPECT_EQ(sha256_file(path("million.txt")),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_F(DigestTest, FilesLargerThanOneBlockDigestAsAWhole) {
  std::string content(5 * 1024 * 1024 / 2 + 17, '\0');
  for (size_t index = 0; index < content.size(); ++index)
    content[index] = static_cast<char>(index * 31);
  write_text(path("large.bin"), content);
  Sha256 whole;
  whole.update(std::as_bytes(std::span(content.data(), content.size())));
  EXPECT_EQ(sha256_file(path("large.bin")), whole.hex_digest());
}

TEST_F(DigestTest, MissingFileIsBadInputNamingIt) {
  try {
    sha256_file(path("absent.obj"));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.file(), path("absent.obj").string());
  }
  EXPECT_THROW(sha256_file(directory_), Error);
}

}  // namespace
}  // namespace hair
