// SHA-256 (core/common/sha256.h) against FIPS 180-4's own examples: the
// digest a stored result's audit states for the data it analysed.

#include "core/common/sha256.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace fog {
namespace {

TEST(Sha256, TheStandardsExamples) {
  EXPECT_EQ(sha256Hex("", 0), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc", 3), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::string two = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";  // two blocks
  EXPECT_EQ(sha256Hex(two.data(), two.size()), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, FedInPiecesGivesTheSameDigest) {
  const std::string million(1000000, 'a');
  Sha256 h;
  for (std::size_t at = 0; at < million.size(); at += 4099)  // pieces across block boundaries
    h.update(reinterpret_cast<const unsigned char*>(million.data()) + at, std::min<std::size_t>(4099, million.size() - at));
  EXPECT_EQ(h.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

}  // namespace
}  // namespace fog
