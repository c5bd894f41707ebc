// Base64 encoding. Expected strings: the test vectors of RFC 4648, section 10, and a byte
// pattern decoded back by Python's base64 module (through meshio's reader in the VTU tests).
#include <string>

#include <gtest/gtest.h>

#include <bimrock/io/base64.hpp>

namespace bimrock {
namespace {

std::string encode(const std::string& s) {
  std::string out;
  append_base64(out, s.data(), s.size());
  return out;
}

TEST(Base64, Rfc4648TestVectors) {
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
}

TEST(Base64, HighBitsAndAppending) {
  // 0xFB 0xFF 0xBF: 111110 111111 111110 111111 -> "+/+/" (the last two letters of the
  // alphabet); appended after what `out` holds.
  std::string out = "x";
  const unsigned char bytes[] = {0xFB, 0xFF, 0xBF, 0x00};
  append_base64(out, bytes, 4);
  EXPECT_EQ(out, "x+/+/AA==");
}

}  // namespace
}  // namespace bimrock
