#pragma once
// Status and Result: how core reports failure. No exception crosses a module
// boundary; a failed call returns a code and a message a user can act on
// ("what is wrong and what to do").

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace fog {

enum class StatusCode {
  kOk = 0,
  kInvalidArgument,   // a parameter or configuration is impossible
  kOutOfRange,        // a value is beyond a physical or configured limit
  kInsufficientData,  // too few samples or periods to support a result
  kCorruptData,       // input bytes or values are malformed
  kIoError,           // a file or device could not be read or written
  kNotConverged,      // an iterative fit did not converge
  kInternal,          // a bug: should never be seen
};

const char* statusCodeName(StatusCode code);

class Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}
  static Status ok() { return {}; }

  bool isOk() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  // "invalid argument: frequency must be > 0 Hz"
  std::string toString() const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

inline Status invalidArgument(std::string m) { return {StatusCode::kInvalidArgument, std::move(m)}; }
inline Status outOfRange(std::string m) { return {StatusCode::kOutOfRange, std::move(m)}; }
inline Status insufficientData(std::string m) { return {StatusCode::kInsufficientData, std::move(m)}; }
inline Status corruptData(std::string m) { return {StatusCode::kCorruptData, std::move(m)}; }
inline Status ioError(std::string m) { return {StatusCode::kIoError, std::move(m)}; }

// Returns from the enclosing function (whose return type a Status converts
// to) when expr gives an error Status.
#define FOG_RETURN_IF_ERROR(expr)                   \
  do {                                              \
    ::fog::Status fogStatus_ = (expr);              \
    if (!fogStatus_.isOk()) return fogStatus_;      \
  } while (false)

// A value or the Status that explains why there is none.
template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  Result(Status status) : status_(std::move(status)) {  // NOLINT: implicit by design
    assert(!status_.isOk() && "a Result without a value needs an error status");
  }

  bool isOk() const { return value_.has_value(); }
  explicit operator bool() const { return isOk(); }
  const Status& status() const { return status_; }

  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T& operator*() & { return *value_; }
  const T& operator*() const& { return *value_; }

 private:
  std::optional<T> value_;
  Status status_;
};

}  // namespace fog
