#pragma once
// SHA-256 (FIPS 180-4) without a crypto library dependency: what states which
// session file an export or a catalog row came from, and which data an
// analysis read. Qt-free.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/common/status.h"

namespace fog {

class Sha256 {
 public:
  void update(const unsigned char* p, std::size_t n);
  // Lower-case hex of the digest; the object is spent afterwards.
  std::string hex();

 private:
  void blocks(const unsigned char* p, std::size_t count);  // whole 64-byte blocks
  std::array<std::uint32_t, 8> h_{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                  0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::array<unsigned char, 64> buf_{};
  std::size_t fill_ = 0;
  std::uint64_t total_ = 0;
};

// Lower-case hex SHA-256 of a file's bytes (what `sha256sum FILE` prints).
Result<std::string> sha256OfFile(const std::string& path);
// Of a string's bytes; of `n` bytes at `p`.
std::string sha256Hex(const std::string& bytes);
std::string sha256Hex(const void* p, std::size_t n);

// Whether the CPU's SHA extensions do the work (else portable C++; both give
// the same digest, tests/core/common compares them).
bool sha256UsesCpuExtensions();

}  // namespace fog
