#pragma once
// Wall-clock pacing shared by the simulator and replay sources: stream
// seconds are released at `speed` stream seconds per wall-clock second from
// the first call to streamTimeNowS(). Speed <= 0 or not finite means as fast
// as possible (streamTimeNowS() is then +infinity).

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <thread>

namespace fog::acquisition {

// Where the wall-clock time comes from and how it is waited for: the
// machine's steady clock by default; tests give one that advances only when
// waited on, so pacing can be asserted exactly.
struct WallClock {
  std::function<std::chrono::steady_clock::time_point()> now = [] { return std::chrono::steady_clock::now(); };
  std::function<void(std::chrono::duration<double>)> sleepFor = [](std::chrono::duration<double> d) {
    std::this_thread::sleep_for(d);
  };
};

class PacedClock {
 public:
  explicit PacedClock(double speed, WallClock wall = {})
      : speed_(speed > 0.0 && std::isfinite(speed) ? speed : 0.0), wall_(std::move(wall)) {}

  bool asFastAsPossible() const { return speed_ == 0.0; }
  double speed() const { return speed_; }

  // Stream time that may have been released by now.
  double streamTimeNowS() {
    if (asFastAsPossible()) return std::numeric_limits<double>::infinity();
    const auto now = wall_.now();
    if (!started_) {
      started_ = true;
      start_ = now;
    }
    return std::chrono::duration<double>(now - start_).count() * speed_;
  }

  // Sleeps until stream time `streamS` is due, but never longer than
  // `timeout`. True when it is due now.
  bool waitFor(double streamS, std::chrono::milliseconds timeout) {
    const double now = streamTimeNowS();
    if (streamS <= now) return true;
    const auto due = std::chrono::duration<double>((streamS - now) / speed_);
    if (due <= timeout) {
      wall_.sleepFor(due);
      return true;
    }
    wall_.sleepFor(timeout);
    return false;
  }

 private:
  double speed_;
  WallClock wall_;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_{};
};

}  // namespace fog::acquisition
