#include "core/common/status.h"

#include <cstdio>
#include <cstdlib>

namespace fog {

const char* statusCodeName(StatusCode code) {
  switch (code) {
    case StatusCode::kOk: return "ok";
    case StatusCode::kInvalidArgument: return "invalid argument";
    case StatusCode::kOutOfRange: return "out of range";
    case StatusCode::kInsufficientData: return "insufficient data";
    case StatusCode::kCorruptData: return "corrupt data";
    case StatusCode::kIoError: return "I/O error";
    case StatusCode::kNotConverged: return "not converged";
    case StatusCode::kCancelled: return "cancelled";
    case StatusCode::kInternal: return "internal error";
  }
  return "unknown";
}

std::string Status::toString() const {
  if (isOk()) return "ok";
  return std::string(statusCodeName(code_)) + ": " + message_;
}

void resultHasNoValue(const Status& status) {
  std::fprintf(stderr, "fogbench: internal error: the value of a failed result was used (%s)\n",
               status.toString().c_str());
  std::abort();
}

}  // namespace fog
