#include "core/common/sha256.h"

namespace fog {

std::string sha256Hex(const void* p, std::size_t n) {
  Sha256 h;
  h.update(static_cast<const unsigned char*>(p), n);
  return h.hex();
}

}  // namespace fog
