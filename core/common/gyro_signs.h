#pragma once
// The gyro signs as every view states them (text report, PDF, Results,
// Configure): each axis with its sign, "X +1, Y -1, Z +1". A number that
// depends on the sign convention travels with it (BenchConstants::gyroSign:
// -1 for a gyro axis that counts against the table's).

#include <array>
#include <string>

#include "core/common/test_plan.h"  // Axis, kAxisCount, axisLabel

namespace fog {

inline std::string describeGyroSigns(const std::array<int, kAxisCount>& sign) {
  std::string out;
  for (int a = 0; a < kAxisCount; ++a) {
    if (!out.empty()) out += ", ";
    out += axisLabel(static_cast<Axis>(a));
    out += sign[static_cast<std::size_t>(a)] < 0 ? " -1" : " +1";
  }
  return out;
}

}  // namespace fog
