// libFuzzer entry for what users hand over as text: the CSV import (metadata
// JSON, table and gyro CSV) and a test plan's JSON.
//
// The input is cut at NUL bytes into a plan, a metadata text, a table and a
// gyro file. Each parser must return a value or a status with a message,
// never crash, hang or allocate without bound; an imported recording must
// hold what the importer promises (times increasing within a test point,
// finite samples) and a plan that parses must write back to JSON that parses
// to the same number of points.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/common/test_plan.h"
#include "core/io/csv_import.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> parts(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0 && parts.size() < 4) parts.emplace_back();
    else parts.back().push_back(static_cast<char>(data[i]));
  }
  parts.resize(4);

  if (auto plan = fog::testPlanFromJson(parts[0])) {
    auto again = fog::testPlanFromJson(fog::testPlanToJson(*plan));
    check(again.isOk() && again->points.size() == plan->points.size());
  } else {
    check(!plan.status().message().empty());
  }

  auto imported = fog::io::importCsvTexts(parts[1], parts[2], parts[3]);
  if (!imported) {
    check(!imported.status().message().empty());
    return 0;
  }
  for (const auto& tp : imported->recording.testPoints) {
    for (std::size_t i = 1; i < tp.table.size(); ++i) check(tp.table[i].timeS > tp.table[i - 1].timeS);
    for (const auto& s : tp.table)
      for (double a : s.angleDeg) check(std::isfinite(a));
    for (const auto& s : tp.imu)
      for (double d : s.incrementDeg) check(std::isfinite(d));
  }
  return 0;
}
