#pragma once
// Wall-clock pacing shared by the simulator and replay sources: stream
// seconds are released at `speed` stream seconds per wall-clock second from
// the first call to streamTimeNowS(). Speed <= 0 or not finite means as fast
// as possible (streamTimeNowS() is then +infinity).

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace fog::acquisition {

class PacedClock {
 public:
  explicit PacedClock(double speed) : speed_(speed > 0.0 && std::isfinite(speed) ? speed : 0.0) {}

  bool asFastAsPossible() const { return speed_ == 0.0; }
  double speed() const { return speed_; }

  // Stream time that may have been released by now.
  double streamTimeNowS() {
    if (asFastAsPossible()) return std::numeric_limits<double>::infinity();
    const auto now = std::chrono::steady_clock::now();
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
      std::this_thread::sleep_for(due);
      return true;
    }
    std::this_thread::sleep_for(timeout);
    return false;
  }

 private:
  double speed_;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_{};
};

}  // namespace fog::acquisition
