#pragma once
// Physical constants and unit conversions. Names carry units where the type
// does not (rateDegPerS, delayMs).

#include <numbers>

namespace fog {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kRadPerDeg = kPi / 180.0;
inline constexpr double kDegPerRad = 180.0 / kPi;
inline constexpr double kSecondsPerHour = 3600.0;
inline constexpr double kArcsecPerDeg = 3600.0;
// Sidereal Earth rotation rate, 7.2921150e-5 rad/s.
inline constexpr double kEarthRateDegPerH = 15.041067;
inline constexpr double kSpeedOfLightMPerS = 299792458.0;

constexpr double degPerHourToDegPerS(double v) { return v / kSecondsPerHour; }
// Angle random walk: deg/sqrt(h) -> deg/sqrt(s).
constexpr double degPerSqrtHourToDegPerSqrtS(double v) { return v / 60.0; }

}  // namespace fog
