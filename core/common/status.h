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
  kCancelled,         // the caller asked the work to stop (not a failure)
  kInternal,          // a bug: should never be seen
};

const char* statusCodeName(StatusCode code);


// [[nodiscard]]: a Status returned and ignored is an error nobody sees.
class [[nodiscard]] Status {
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

// Prints the status to stderr and aborts: the value of an error Result was
// used (a bug in the caller, never an input error).
[[noreturn]] void resultHasNoValue(const Status& status);

inline Status invalidArgument(std::string m) { return {StatusCode::kInvalidArgument, std::move(m)}; }
inline Status outOfRange(std::string m) { return {StatusCode::kOutOfRange, std::move(m)}; }
inline Status insufficientData(std::string m) { return {StatusCode::kInsufficientData, std::move(m)}; }
inline Status corruptData(std::string m) { return {StatusCode::kCorruptData, std::move(m)}; }
inline Status ioError(std::string m) { return {StatusCode::kIoError, std::move(m)}; }
inline Status cancelled(std::string m) { return {StatusCode::kCancelled, std::move(m)}; }

// Returns from the enclosing function (whose return type a Status converts
// to) when expr gives an error Status.
#define FOG_RETURN_IF_ERROR(expr)                   \
  do {                                              \
    ::fog::Status fogStatus_ = (expr);              \
    if (!fogStatus_.isOk()) return fogStatus_;      \
  } while (false)

#define FOG_STATUS_CONCAT_INNER_(a, b) a##b
#define FOG_STATUS_CONCAT_(a, b) FOG_STATUS_CONCAT_INNER_(a, b)

// Evaluates a Result; on an error, returns its Status from the enclosing
// function, otherwise moves the value into lhs, which may declare it:
//   FOG_ASSIGN_OR_RETURN(auto plan, loadPlan(path));
//   FOG_ASSIGN_OR_RETURN(info.plan, loadPlan(path));
#define FOG_ASSIGN_OR_RETURN(lhs, ...) \
  FOG_ASSIGN_OR_RETURN_IMPL_(FOG_STATUS_CONCAT_(fogResult_, __LINE__), lhs, __VA_ARGS__)
#define FOG_ASSIGN_OR_RETURN_IMPL_(result, lhs, ...) \
  auto result = (__VA_ARGS__);                       \
  if (!result.isOk()) return result.status();        \
  lhs = std::move(result).value()

// A value or the Status that explains why there is none.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  Result(Status status) : status_(std::move(status)) {  // NOLINT: implicit by design
    assert(!status_.isOk() && "a Result without a value needs an error status");
  }

  bool isOk() const { return value_.has_value(); }
  explicit operator bool() const { return isOk(); }
  const Status& status() const { return status_; }

  // Reaching the value of an error Result is a bug in the caller: it stops
  // the program with the Result's message, in every build type, rather than
  // reading an empty optional (undefined behaviour).
  T& value() & { return checked(); }
  const T& value() const& { return checked(); }
  T&& value() && { return std::move(checked()); }
  T* operator->() { return &checked(); }
  const T* operator->() const { return &checked(); }
  T& operator*() & { return checked(); }
  const T& operator*() const& { return checked(); }

 private:
  T& checked() {
    if (!value_) resultHasNoValue(status_);
    return *value_;
  }
  const T& checked() const {
    if (!value_) resultHasNoValue(status_);
    return *value_;
  }

  std::optional<T> value_;
  Status status_;
};

}  // namespace fog
