// SHA-256 (core/common/sha256.h): FIPS 180-4's examples, and the CPU's SHA
// extensions against the portable code on every length around the block
// boundaries and on data fed in odd pieces.

#include "core/common/sha256.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>

namespace fog {
namespace {

// allDigests() from a child process with the portable code forced
// (the choice is made once per process).
std::string portableDigests(const std::string& program) {
  const std::string cmd = "FOG_SHA256_PORTABLE=1 " + program + " --gtest_filter=Sha256.PrintDigests";
  FILE* p = ::popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr);
  std::string out;
  char buf[4096];
  std::size_t n;
  while (p && (n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  if (p) ::pclose(p);
  return out;
}

std::string testData(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::string s(n, '\0');
  for (auto& c : s) c = static_cast<char>(rng() & 0xFF);
  return s;
}

// Digests of lengths 0..300 and of 1 MiB + 7, fed whole and in pieces of
// 1, 63, 65 and 4097 bytes; one line each.
std::string allDigests() {
  std::string out;
  auto pieces = [](const std::string& data, std::size_t piece) {
    Sha256 h;
    for (std::size_t at = 0; at < data.size(); at += piece)
      h.update(reinterpret_cast<const unsigned char*>(data.data()) + at, std::min(piece, data.size() - at));
    return h.hex();
  };
  for (std::size_t n = 0; n <= 300; ++n) out += sha256Hex(testData(n, static_cast<unsigned>(n))) + "\n";
  const std::string big = testData((1u << 20) + 7, 99);
  for (std::size_t piece : {big.size(), std::size_t{1}, std::size_t{63}, std::size_t{65}, std::size_t{4097}})
    out += pieces(big, piece) + "\n";
  return out;
}

TEST(Sha256, Fips180Examples) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// Run by the test below in a child process: prints allDigests().
TEST(Sha256, PrintDigests) {
  if (!std::getenv("FOG_SHA256_PORTABLE")) GTEST_SUCCEED() << "only prints in the child process";
  else std::fputs(("DIGESTS\n" + allDigests()).c_str(), stdout);
}

TEST(Sha256, CpuExtensionsAndPortableCodeAgree) {
  const std::string here = allDigests();
  const std::string child = portableDigests("/proc/" + std::to_string(::getpid()) + "/exe");
  const auto at = child.find("DIGESTS\n");
  ASSERT_NE(at, std::string::npos) << child;
  const std::string portable = child.substr(at + 8, here.size());
  EXPECT_EQ(here, portable) << (sha256UsesCpuExtensions() ? "SHA extensions in use here"
                                                          : "no SHA extensions here: both portable");
  // Two different inputs never share these digests (the comparison above
  // would pass on a constant).
  EXPECT_NE(sha256Hex("a"), sha256Hex("b"));
}

}  // namespace
}  // namespace fog
