#include "core/io/csv_import.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string_view>
#include <system_error>

#include "core/common/file_read.h"
#include "core/common/text.h"
#include "core/io/metadata.h"

namespace fog::io {

namespace {

namespace fs = std::filesystem;

// Each file of an import: a regular file of at most kMaxImportFileBytes
// (file_read.h: a FIFO or a device is refused before it is opened).
Result<std::string> readWholeFile(const std::string& path) {
  FOG_ASSIGN_OR_RETURN(auto text, readRegularTextFile(path, kMaxImportFileBytes, "an import file"));
  // A UTF-8 byte-order mark, as some spreadsheets write it.
  if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  return text;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Walks the lines of a CSV text, skipping blank lines and '#' comments;
// counts every physical line so that errors point at the right one.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // False at the end of the text.
  bool next(std::string_view& line) {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view raw = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++lineNo_;
      if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
      const std::string_view t = trim(raw);
      if (t.empty() || t.front() == '#') continue;
      line = raw;
      return true;
    }
    return false;
  }
  std::size_t lineNo() const { return lineNo_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t lineNo_ = 0;
};

void splitFields(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      out.push_back(trim(line.substr(start)));
      return;
    }
    out.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

// Columns a stream may have. Index in this list = column id.
constexpr std::array<const char*, 5> kTableColumns = {"test_point", "time_s", "x_deg", "y_deg", "z_deg"};
constexpr std::array<const char*, 10> kGyroColumns = {
    "test_point",  "time_s",       "x_inc_deg",    "y_inc_deg",    "z_inc_deg",
    "temperature_c", "lost_before", "x_rate_deg_s", "y_rate_deg_s", "z_rate_deg_s"};
enum Column { kTestPoint = 0, kTime = 1, kAxis0 = 2, kTemperature = 5, kLostBefore = 6, kRate0 = 7 };

std::string list(const char* const* names, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    if (i) s += ',';
    s += names[i];
  }
  return s;
}

// The range a CSV value may take, with its unit and the reason for the bound.
struct ValueRange {
  double min, max;
  const char* what;  // "a time stamp (s)", for messages
  const char* why;   // the bound's reason, for messages
};

// One data file being parsed: where to find each column, and how to word errors.
class CsvStream {
 public:
  CsvStream(std::string path, const std::string& text, const char* const* names, std::size_t count)
      : path_(std::move(path)), lines_(text), names_(names), count_(count), where_(count, -1) {}

  // Reads the header line. Unknown, duplicate or empty names are refused.
  Status readHeader() {
    std::string_view line;
    if (!lines_.next(line))
      return corruptData(path_ + " is empty: it needs a header line (" + list(names_, count_) +
                         ") and data rows (docs/formats.md)");
    headerLine_ = lines_.lineNo();
    splitFields(line, fields_);
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      const std::string name(fields_[i]);
      int id = -1;
      for (std::size_t k = 0; k < count_; ++k)
        if (name == names_[k]) id = static_cast<int>(k);
      if (id < 0) {
        // A column that looks like a rate points to the rules for rates.
        const bool rateLike = name.find("rate") != std::string::npos || name.find("dps") != std::string::npos ||
                              name.find("deg_s") != std::string::npos || name.find("deg/s") != std::string::npos;
        return corruptData(path_ + " line " + std::to_string(headerLine_) + ", column " + std::to_string(i + 1) +
                           ": unknown column \"" + name + "\"; this file takes the columns " + list(names_, count_) +
                           " (any order); rename or delete the column" +
                           (rateLike ? ". Gyro rates are read as x_rate_deg_s, y_rate_deg_s, z_rate_deg_s in the gyro "
                                       "file, with bench.gyro_rate_convention (\"frame_average\" or "
                                       "\"sample_at_stamp\") and bench.gyro_frame_period_ms in the metadata "
                                       "(docs/formats.md, \"Rates\")"
                                     : ""));
      }
      if (where_[static_cast<std::size_t>(id)] >= 0)
        return corruptData(path_ + " line " + std::to_string(headerLine_) + ": column \"" + name +
                           "\" appears twice; keep one");
      where_[static_cast<std::size_t>(id)] = static_cast<int>(i);
    }
    columns_ = fields_.size();
    return Status::ok();
  }

  bool has(int id) const { return static_cast<std::size_t>(id) < count_ && where_[static_cast<std::size_t>(id)] >= 0; }
  const std::string& path() const { return path_; }
  std::size_t lineNo() const { return lines_.lineNo(); }

  // Next data row; false at the end. Fails on a wrong number of values.
  Result<bool> nextRow() {
    std::string_view line;
    if (!lines_.next(line)) return false;
    splitFields(line, fields_);
    if (fields_.size() != columns_)
      return corruptData(path_ + " line " + std::to_string(lines_.lineNo()) + ": " + std::to_string(fields_.size()) +
                         " values, but the header (line " + std::to_string(headerLine_) + ") has " +
                         std::to_string(columns_) + " columns; every row needs one value per column, "
                         "separated by ',' (the decimal point is '.')");
    return true;
  }

  std::string_view field(int id) const {
    return fields_[static_cast<std::size_t>(where_[static_cast<std::size_t>(id)])];
  }

  Status error(int id, const std::string& what) const {
    return corruptData(path_ + " line " + std::to_string(lines_.lineNo()) + ", column \"" + names_[id] +
                       "\": " + what);
  }

  // The field as the user wrote it, in quotes, for messages.
  std::string quoted(int id) const {
    std::string q(1, '"');
    q.append(field(id));
    q += '"';
    return q;
  }

  // A finite double within [-limit.maxAbs, limit.maxAbs] (or [limit.min,
  // limit.maxAbs]): std::from_chars, locale-independent, the whole field. The
  // ranges are physical (ValueRange below): a value far beyond them is a unit
  // or column error, and near the double's range its square overflows the fits.
  Status number(int id, double& out, const ValueRange& range) const;
  Status finiteNumber(int id, double& out) const {
    std::string_view s = field(id);
    if (s.empty()) return error(id, "empty value; every row needs a number here");
    if (s.front() == '+') s.remove_prefix(1);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec == std::errc::result_out_of_range) return error(id, quoted(id) + " is out of the range of a double");
    if (ec != std::errc() || end != s.data() + s.size())
      return error(id, quoted(id) + " is not a number (write e.g. 1.25 or -3.5e-05; the decimal point is '.')");
    if (!std::isfinite(out))
      return error(id, quoted(id) + " is not finite; NaN and infinity are refused: drop the row or fill the gap");
    return Status::ok();
  }

  Status integer(int id, std::uint64_t& out, std::uint64_t min, std::uint64_t max, const char* meaning) const {
    const std::string_view s = field(id);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty() || out < min || out > max)
      return error(id, quoted(id) + " is not " + meaning);
    return Status::ok();
  }

 private:
  std::string path_;
  LineReader lines_;
  const char* const* names_;
  std::size_t count_;
  std::vector<int> where_;  // column id -> field position, -1 when absent
  std::vector<std::string_view> fields_;
  std::size_t columns_ = 0, headerLine_ = 0;
};

// Seconds: at 1e10 s a double still resolves 2 us; a Unix time stamp is 1.8e9 s.
constexpr ValueRange kTimeRange{-1e10, 1e10, "a time stamp (s)",
                                "seconds on the common clock; beyond 1e10 s a double no longer resolves microseconds"};
// Degrees: a million turns of a continuously rotating table.
constexpr ValueRange kAngleRange{-3.6e8, 3.6e8, "a table angle (deg)", "a million turns of the table"};
// A gyro frame's increment: 1e4 deg is over 27 turns in one frame.
constexpr ValueRange kIncrementRange{-1e4, 1e4, "a gyro increment (deg)",
                                     "over 27 turns in one IMU frame; check the column's unit"};
// A rate: 1e6 deg/s is some 300 times a navigation FOG's range.
constexpr ValueRange kRateRange{-1e6, 1e6, "a gyro rate (deg/s)", "far beyond any gyro's range; check the unit"};
constexpr ValueRange kTemperatureRange{-273.15, 1000.0, "a temperature (deg C)", "degrees Celsius"};

Status CsvStream::number(int id, double& out, const ValueRange& range) const {
  FOG_RETURN_IF_ERROR(finiteNumber(id, out));
  if (out < range.min || out > range.max)
    return error(id, quoted(id) + " is out of range for " + range.what + ": it must be within " +
                         printfNumber("%g", range.min) + " .. " + printfNumber("%g", range.max) + " (" + range.why + ")");
  return Status::ok();
}

// Per test point, the last time seen and its line: times must increase
// strictly within a test point (analysis and the increment model need it).
struct TimeCheck {
  std::vector<double> last;
  std::vector<std::size_t> line;
  explicit TimeCheck(std::size_t n) : last(n, -HUGE_VAL), line(n, 0) {}
};

Status testPointOf(const CsvStream& s, std::size_t count, std::size_t& tp) {
  if (!s.has(kTestPoint)) {
    tp = 0;
    return Status::ok();
  }
  std::uint64_t v = 0;
  const std::string meaning =
      "a test point number from 1 to " + std::to_string(count) + " (metadata lists " + std::to_string(count) + ")";
  FOG_RETURN_IF_ERROR(s.integer(kTestPoint, v, 1, count, meaning.c_str()));
  tp = static_cast<std::size_t>(v - 1);
  return Status::ok();
}

Status timeOf(const CsvStream& s, std::size_t tp, TimeCheck& check, double& t) {
  FOG_RETURN_IF_ERROR(s.number(kTime, t, kTimeRange));
  if (!(t > check.last[tp]))
    return s.error(kTime, std::string(s.field(kTime)) + " s is not after the previous time of test point " +
                              std::to_string(tp + 1) + " (line " + std::to_string(check.line[tp]) +
                              "); times must increase strictly within a test point: sort the rows by time "
                              "and drop duplicates");
  check.last[tp] = t;
  check.line[tp] = s.lineNo();
  return Status::ok();
}

Status needsTestPointColumn(const CsvStream& s, std::size_t count) {
  if (count > 1 && !s.has(kTestPoint))
    return corruptData(s.path() + " has no \"test_point\" column, but the metadata lists " + std::to_string(count) +
                       " test points; add the column (1 .. " + std::to_string(count) + ") to say which row is which");
  return Status::ok();
}

// The frame shared by both files: header with a time column and at least one
// axis column (noAxisColumn says which), the test point column when there is
// more than one, strictly increasing times per test point, at least one row.
// row(tp, timeS) reads the rest of each row.
bool hasAny(const CsvStream& s, int first) { return s.has(first) || s.has(first + 1) || s.has(first + 2); }

template <typename ReadRow>
Status parseRows(CsvStream& s, std::size_t pointCount, std::uint64_t& samplesSoFar, const std::string& noAxisColumn,
                 const ReadRow& row) {
  FOG_RETURN_IF_ERROR(s.readHeader());
  if (!s.has(kTime)) return corruptData(s.path() + ": missing column \"time_s\" (seconds on the common clock)");
  const bool rates = s.has(kRate0) || s.has(kRate0 + 1) || s.has(kRate0 + 2);
  if (hasAny(s, kAxis0) && rates)
    return corruptData(s.path() + ": both increment (*_inc_deg) and rate (*_rate_deg_s) columns; give one kind");
  if (!hasAny(s, kAxis0) && !rates) return corruptData(s.path() + ": " + noAxisColumn);
  FOG_RETURN_IF_ERROR(needsTestPointColumn(s, pointCount));
  TimeCheck check(pointCount);
  std::size_t rows = 0;
  while (true) {
    FOG_ASSIGN_OR_RETURN(auto more, s.nextRow());
    if (!more) break;
    ++rows;
    // The run's memory budget (test_plan.h) holds for imports too: a session
    // every command could read again, refused before the rows are held.
    if (++samplesSoFar > kMaxRunSamples)
      return corruptData(s.path() + " line " + std::to_string(s.lineNo()) + ": the import holds more than " +
                         std::to_string(kMaxRunSamples) + " table and gyro rows in all, the memory budget of a "
                         "session (an hour at 1 kHz / 500 Hz, docs/reliability.md); split it into several imports");
    std::size_t tp = 0;
    FOG_RETURN_IF_ERROR(testPointOf(s, pointCount, tp));
    double timeS = 0.0;
    FOG_RETURN_IF_ERROR(timeOf(s, tp, check, timeS));
    FOG_RETURN_IF_ERROR(row(tp, timeS));
  }
  if (rows == 0) return corruptData(s.path() + " has a header but no data rows");
  return Status::ok();
}

Status parseTable(CsvStream& s, std::vector<TestPointData>& points, std::uint64_t& samplesSoFar) {
  return parseRows(s, points.size(), samplesSoFar, "no angle column; give at least the swing axis' one (x_deg, y_deg or z_deg)",
                   [&](std::size_t tp, double timeS) {
                     TableSample sample;
                     sample.timeS = timeS;
                     for (int a = 0; a < kAxisCount; ++a)
                       if (s.has(kAxis0 + a))
                         FOG_RETURN_IF_ERROR(s.number(kAxis0 + a, sample.angleDeg[static_cast<std::size_t>(a)], kAngleRange));
                     points[tp].table.push_back(sample);
                     return Status::ok();
                   });
}

// Rows of a rate file hold the rates (deg/s) in incrementDeg until
// convertRates() turns them into increments.
Status parseGyro(CsvStream& s, std::vector<TestPointData>& points, std::uint64_t& samplesSoFar) {
  return parseRows(
      s, points.size(), samplesSoFar,
      "no increment column; give at least the swing axis' one (x_inc_deg, y_inc_deg or z_inc_deg), or rates "
      "(x_rate_deg_s ...) with their convention in the metadata",
      [&](std::size_t tp, double timeS) {
        ImuSample sample;
        sample.timeS = timeS;
        for (int a = 0; a < kAxisCount; ++a) {
          if (s.has(kAxis0 + a))
            FOG_RETURN_IF_ERROR(s.number(kAxis0 + a, sample.incrementDeg[static_cast<std::size_t>(a)], kIncrementRange));
          if (s.has(kRate0 + a))
            FOG_RETURN_IF_ERROR(s.number(kRate0 + a, sample.incrementDeg[static_cast<std::size_t>(a)], kRateRange));
        }
        if (s.has(kTemperature)) FOG_RETURN_IF_ERROR(s.number(kTemperature, sample.temperatureC, kTemperatureRange));
        if (s.has(kLostBefore)) {
          std::uint64_t lost = 0;
          FOG_RETURN_IF_ERROR(
              s.integer(kLostBefore, lost, 0, 0xFFFFFFFFu, "a count of lost IMU frames (an integer >= 0)"));
          sample.lostBefore = static_cast<std::uint32_t>(lost);
        }
        points[tp].imu.push_back(sample);
        return Status::ok();
      });
}

// Turns rates (deg/s, held in incrementDeg) into increments, exactly as
// their convention says (docs/formats.md, "Rates"). Sample-and-hold rows (a
// board that read the IMU faster than it sends repeats each value) are
// dropped first: the first row of each run is where the new value arrived.
Status convertRates(std::vector<TestPointData>& points, const detail::Metadata& meta, const std::string& gyroPath,
                    const std::string& metaPath, std::vector<std::string>& notes) {
  if (meta.rateConvention == detail::RateConvention::kNone)
    return corruptData(gyroPath + " holds rates (*_rate_deg_s), but " + metaPath +
                       " does not say how they were sampled: set bench.gyro_rate_convention to \"frame_average\" "
                       "(each rate is its frame's angle increment over the IMU's frame period; also give "
                       "bench.gyro_frame_period_ms) or \"sample_at_stamp\" (each rate is the rate at its row's time "
                       "stamp). The choice moves the delay by about half a frame, so it is never guessed "
                       "(docs/formats.md, \"Rates\")");
  const bool frameAverage = meta.rateConvention == detail::RateConvention::kFrameAverage;
  if (frameAverage && !(meta.gyroFramePeriodMs > 0.0))
    return corruptData(metaPath + ": bench.gyro_rate_convention \"frame_average\" needs bench.gyro_frame_period_ms, "
                                  "the IMU's own frame period (increment = rate x frame period; the differences of "
                                  "the bench's stamps carry their jitter)");
  std::size_t dropped = 0;
  double holdShiftS = 0.0;
  for (auto& p : points) {
    auto& imu = p.imu;
    if (imu.size() < 3) continue;
    std::vector<double> readIntervals;
    for (std::size_t k = 1; k < imu.size(); ++k) readIntervals.push_back(imu[k].timeS - imu[k - 1].timeS);
    // A held value repeats sooner than the IMU sends a frame; two real frames
    // may carry the same (quantised) rate, but about a frame period apart. The
    // frame period is the stated one, or the typical time between changes.
    std::vector<double> changes;
    double lastChange = imu.front().timeS;
    std::size_t repeats = 0;
    for (std::size_t k = 1; k < imu.size(); ++k) {
      if (imu[k].incrementDeg == imu[k - 1].incrementDeg) {
        ++repeats;
        continue;
      }
      changes.push_back(imu[k].timeS - lastChange);
      lastChange = imu[k].timeS;
    }
    if (repeats * 5 < imu.size() || changes.empty()) continue;  // no sample-and-hold
    double frameS = meta.gyroFramePeriodMs * 1e-3;
    if (!(frameS > 0.0)) {
      std::nth_element(changes.begin(), changes.begin() + static_cast<std::ptrdiff_t>(changes.size() / 2), changes.end());
      frameS = changes[changes.size() / 2];
    }
    std::vector<ImuSample> kept{imu.front()};
    for (std::size_t k = 1; k < imu.size(); ++k)
      if (imu[k].incrementDeg != kept.back().incrementDeg || imu[k].timeS - kept.back().timeS > 0.9 * frameS)
        kept.push_back(imu[k]);
    dropped += imu.size() - kept.size();
    // The first read after a frame arrived comes on average half a read
    // interval later: the kept rows move back by that mean wait.
    std::nth_element(readIntervals.begin(), readIntervals.begin() + static_cast<std::ptrdiff_t>(readIntervals.size() / 2),
                     readIntervals.end());
    holdShiftS = 0.5 * readIntervals[readIntervals.size() / 2];
    for (auto& s : kept) s.timeS -= holdShiftS;
    imu = std::move(kept);
  }
  for (auto& p : points) {
    auto& imu = p.imu;
    if (imu.empty()) continue;
    if (frameAverage) {
      const double frameS = meta.gyroFramePeriodMs * 1e-3;
      for (auto& s : imu)
        for (auto& v : s.incrementDeg) v *= frameS;
    } else {
      // Trapezoid between stamps: symmetric about the interval's middle, so
      // it adds no delay; across lost frames it covers the whole gap.
      std::vector<std::array<double, kAxisCount>> rate(imu.size());
      for (std::size_t k = 0; k < imu.size(); ++k) rate[k] = imu[k].incrementDeg;
      for (std::size_t k = 0; k < imu.size(); ++k)
        for (std::size_t a = 0; a < kAxisCount; ++a)
          imu[k].incrementDeg[a] = k == 0 ? 0.0 : 0.5 * (rate[k][a] + rate[k - 1][a]) * (imu[k].timeS - imu[k - 1].timeS);
      for (auto& s : imu) s.lostBefore = 0;
    }
  }
  notes.push_back(std::string("gyro rates converted to increments: ") +
                  (frameAverage ? "frame averages x " + std::to_string(meta.gyroFramePeriodMs).substr(0, 6) +
                                      " ms frame period"
                                : "rates at the stamps, integrated between stamps (trapezoid)"));
  if (dropped > 0) {
    char wait[160];
    std::snprintf(wait, sizeof wait, "%.4g ms (+/- %.2g ms if reads and frames are locked)", holdShiftS * 1e3,
                  holdShiftS * 2e3 / std::sqrt(12.0));
    notes.push_back("dropped " + std::to_string(dropped) +
                    " repeated gyro rows (sample-and-hold: the bench read the IMU faster than it sends); the first "
                    "row of each value is kept and moved back by the mean wait between a frame's arrival and the "
                    "bench's next read, " + std::string(wait));
  }
  return Status::ok();
}

// "import A (recorded by: import B (recorded by: bench))" never nests: an
// import of an export of an import keeps the original recorder's words.
std::string originalSource(std::string source) {
  while (source.rfind("import ", 0) == 0) {
    const auto at = source.find(" (recorded by: ");
    if (at == std::string::npos) return {};
    source = source.substr(at + 15);
    if (!source.empty() && source.back() == ')') source.pop_back();
  }
  return source;
}

// The user's rate convention and frame period join the metadata's; where
// both state one they must agree (the convention moves the delay by about
// half a frame: two answers are never reconciled by a guess).
Status applyRateOptions(detail::Metadata& meta, const ImportOptions& options, const std::string& metaPath) {
  if (!options.gyroRateConvention.empty()) {
    const detail::RateConvention given = detail::rateConventionFromName(options.gyroRateConvention);
    if (given == detail::RateConvention::kNone)
      return invalidArgument("the gyro rate convention must be \"frame_average\" or \"sample_at_stamp\", not \"" +
                             options.gyroRateConvention + "\"");
    if (meta.rateConvention != detail::RateConvention::kNone && meta.rateConvention != given)
      return invalidArgument(metaPath + " states bench.gyro_rate_convention \"" +
                             detail::rateConventionName(meta.rateConvention) + "\", the import was asked for \"" +
                             options.gyroRateConvention + "\": correct the one that is wrong");
    meta.rateConvention = given;
  }
  if (options.gyroFramePeriodMs != 0.0) {
    if (!(options.gyroFramePeriodMs >= detail::kMinFramePeriodMs && options.gyroFramePeriodMs <= detail::kMaxFramePeriodMs))
      return invalidArgument("the IMU's frame period must be within " + fixed(detail::kMinFramePeriodMs, 3) + " .. " +
                             fixed(detail::kMaxFramePeriodMs, 0) + " ms");
    if (meta.gyroFramePeriodMs > 0.0 && meta.gyroFramePeriodMs != options.gyroFramePeriodMs)
      return invalidArgument(metaPath + " states bench.gyro_frame_period_ms " + printfNumber("%.9g", meta.gyroFramePeriodMs) +
                             ", the import was asked for " + printfNumber("%.9g", options.gyroFramePeriodMs) +
                             " ms: correct the one that is wrong");
    meta.gyroFramePeriodMs = options.gyroFramePeriodMs;
  }
  return Status::ok();
}

// Cuts a continuous recording at its swing windows as `spec` says ("auto" or
// "S-E,..."), and records what was applied in the session's import settings.
Status applySegmentation(ImportedSession& imported, const std::string& spec) {
  auto& points = imported.recording.testPoints;
  Result<std::vector<analysis::SwingWindow>> windows = invalidArgument("no segmentation");
  if (spec == "auto") {
    if (points.size() != 1)
      return invalidArgument("automatic segmentation cuts one continuous recording; this import holds " +
                             std::to_string(points.size()) + " test points already");
    windows = analysis::findSwingWindows(points.front().table, points.front().axis);
  } else {
    windows = analysis::parseSwingWindows(spec);
  }
  if (!windows) return windows.status();
  FOG_RETURN_IF_ERROR(splitIntoSwingWindows(imported, *windows));
  std::string applied = spec == "auto" ? "auto: " : "given: ";
  for (std::size_t i = 0; i < windows->size(); ++i) {
    if (i > 0) applied += ',';
    applied += printfNumber("%.6f", (*windows)[i].startS);
    applied += '-';
    applied += printfNumber("%.6f", (*windows)[i].endS);
  }
  imported.info.imported.segmentation = applied;
  imported.windows = std::move(*windows);
  return Status::ok();
}

Result<ImportedSession> importTexts(const std::string& what, const std::string& metaPath,
                                    const std::string& metaText, const std::string& tablePath,
                                    const std::string& tableText, const std::string& gyroPath,
                                    const std::string& gyroText, const ImportOptions& options) {
  FOG_ASSIGN_OR_RETURN(auto meta, detail::metadataFromJson(metaPath, metaText));
  FOG_RETURN_IF_ERROR(applyRateOptions(meta, options, metaPath));
  const std::size_t count = meta.testPoints.size();
  std::vector<TestPointData> points(count);
  for (std::size_t i = 0; i < count; ++i) {
    points[i].index = static_cast<int>(i);
    points[i].axis = meta.testPoints[i].axis;
    points[i].nominalFrequencyHz = meta.testPoints[i].frequencyHz;
    points[i].nominalAmplitudeDeg = meta.testPoints[i].amplitudeDeg;
  }

  CsvStream table(tablePath, tableText, kTableColumns.data(), kTableColumns.size());
  std::uint64_t samples = 0;
  FOG_RETURN_IF_ERROR(parseTable(table, points, samples));
  CsvStream gyro(gyroPath, gyroText, kGyroColumns.data(), kGyroColumns.size());
  FOG_RETURN_IF_ERROR(parseGyro(gyro, points, samples));

  ImportedSession out;
  // The swing axis must be there; the others are read as 0 (another bench may
  // record only the axis it swings).
  for (const auto& p : points) {
    if (p.table.empty() && p.imu.empty()) continue;
    const int a = static_cast<int>(p.axis);
    if (!table.has(kAxis0 + a))
      return corruptData(tablePath + ": no \"" + kTableColumns[static_cast<std::size_t>(kAxis0 + a)] +
                         "\" column, but test point " + std::to_string(p.index + 1) + " swings the " + axisLabel(p.axis) +
                         " axis (" + metaPath + "); add the column or correct the axis");
    if (!gyro.has(kAxis0 + a) && !gyro.has(kRate0 + a))
      return corruptData(gyroPath + ": no \"" + kGyroColumns[static_cast<std::size_t>(kAxis0 + a)] +
                         "\" column, but test point " + std::to_string(p.index + 1) + " swings the " + axisLabel(p.axis) +
                         " axis (" + metaPath + "); add the column or correct the axis");
  }
  // (Axis and temperature columns the docs allow to leave out read as 0
  // without a note: only what the user must know is said.)
  if (hasAny(gyro, kRate0)) FOG_RETURN_IF_ERROR(convertRates(points, meta, gyroPath, metaPath, out.notes));
  // The increments stay as recorded: the signs go with the session's bench
  // constants, and the analysis negates them where they enter, as for a
  // live session.
  for (int a = 0; a < kAxisCount; ++a)
    if (meta.info.bench.gyroSign[static_cast<std::size_t>(a)] < 0)
      out.notes.push_back(std::string("gyro ") + axisLabel(static_cast<Axis>(a)) +
                          " axis mounted the other way round (bench.gyro_sign -1): the analysis negates its "
                          "increments");

  SessionInfo& info = out.info;
  info = meta.info;
  const std::string original = originalSource(meta.info.source);
  info.source = "import " + what + (original.empty() ? "" : " (recorded by: " + original + ")");
  Recording& rec = out.recording;
  rec.counterHz = info.bench.counterHz;
  rec.counterBits = info.bench.counterBits;
  // The increments are in degrees; a pulse equivalent > 0 tells the analysis so.
  rec.pulseEquivalentDeg = info.bench.pulseEquivalentDeg;
  StreamHealth counted;
  for (std::size_t i = 0; i < count; ++i) {
    auto& p = points[i];
    const auto& m = meta.testPoints[i];
    TestPoint plan;
    plan.axis = m.axis;
    plan.frequencyHz = m.frequencyHz;
    plan.amplitudeDeg = m.amplitudeDeg;
    plan.durationS = m.hasPlan ? m.durationS : (p.table.size() > 1 ? p.table.back().timeS - p.table.front().timeS : 0.0);
    plan.settleS = m.settleS;
    plan.startPhaseDeg = m.startPhaseDeg;
    plan.kind = m.kind;
    p.kind = m.kind;
    info.plan.points.push_back(plan);

    counted.tableFrames += p.table.size();
    counted.imuFrames += p.imu.size();
    for (const auto& s : p.imu) counted.lostFrames += s.lostBefore;
    if (p.table.empty() && p.imu.empty()) {
      out.notes.push_back("test point " + std::to_string(i + 1) + " has no data in either file; left out");
      continue;
    }
    if (p.table.empty() || p.imu.empty())
      out.notes.push_back("test point " + std::to_string(i + 1) + " has no " + (p.table.empty() ? "table" : "gyro") +
                          " rows; it cannot give a delay");
    rec.testPoints.push_back(std::move(p));
  }
  rec.health = meta.hasStream ? meta.stream : counted;
  if (rec.testPoints.empty()) return corruptData(what + " holds no data for any test point");
  if (hasAny(gyro, kRate0)) {
    info.imported.gyroRateConvention = detail::rateConventionName(meta.rateConvention);
    info.imported.gyroFramePeriodMs = meta.gyroFramePeriodMs;
  }
  if (!options.segmentation.empty()) FOG_RETURN_IF_ERROR(applySegmentation(out, options.segmentation));
  return out;
}

}  // namespace

Result<ImportedSession> importCsvDirectory(const std::string& dir, const ImportOptions& options) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    return ioError(dir + " is not a directory; give the directory that holds metadata.json, table.csv and gyro.csv");
  const fs::path d(dir);
  const std::string metaPath = (d / "metadata.json").string();
  const std::string tablePath = (d / "table.csv").string();
  const std::string gyroPath = (d / "gyro.csv").string();
  FOG_ASSIGN_OR_RETURN(auto meta, readWholeFile(metaPath));
  FOG_ASSIGN_OR_RETURN(auto table, readWholeFile(tablePath));
  FOG_ASSIGN_OR_RETURN(auto gyro, readWholeFile(gyroPath));
  return importTexts(dir, metaPath, meta, tablePath, table, gyroPath, gyro, options);
}

Result<ImportedSession> importCsvTexts(const std::string& metadataText, const std::string& tableText,
                                       const std::string& gyroText, const ImportOptions& options) {
  return importTexts("(texts)", "metadata.json", metadataText, "table.csv", tableText, "gyro.csv", gyroText, options);
}

Result<ImportedSession> importCsvFiles(const std::vector<std::string>& paths, const ImportOptions& options) {
  if (paths.size() != 3)
    return invalidArgument("give three files (metadata JSON, table CSV, gyro CSV), not " +
                           std::to_string(paths.size()));
  std::optional<std::size_t> meta, table, gyro;
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    FOG_ASSIGN_OR_RETURN(auto text, readWholeFile(paths[i]));
    texts.push_back(std::move(text));
    const std::string& t = texts.back();
    const auto first = t.find_first_not_of(" \t\r\n");
    std::optional<std::size_t>* slot = nullptr;
    const char* kind = "";
    if (first != std::string::npos && t[first] == '{') {
      slot = &meta;
      kind = "metadata";
    } else {
      // Identified by the header's names, so a file may be called anything.
      LineReader lines(t);
      std::string_view header;
      std::vector<std::string_view> names;
      if (!lines.next(header))
        return corruptData(paths[i] + " is empty: a table or gyro file needs a header line and data rows, "
                                      "metadata a JSON object (docs/formats.md)");
      splitFields(header, names);
      auto hasName = [&](const char* n) { return std::find(names.begin(), names.end(), n) != names.end(); };
      if (hasName("x_inc_deg") || hasName("y_inc_deg") || hasName("z_inc_deg")) {
        slot = &gyro;
        kind = "gyro";
      } else if (hasName("x_deg") || hasName("y_deg") || hasName("z_deg")) {
        slot = &table;
        kind = "table";
      } else {
        return invalidArgument("cannot tell what " + paths[i] +
                               " holds: it is not JSON metadata and its header has neither an angle column "
                               "(x_deg, y_deg, z_deg) nor an increment column (x_inc_deg, y_inc_deg, z_inc_deg)");
      }
    }
    if (slot->has_value())
      return invalidArgument("both " + paths[**slot] + " and " + paths[i] + " look like the " + kind +
                             " file; give one metadata, one table and one gyro file");
    *slot = i;
  }
  if (!meta || !table || !gyro)
    return invalidArgument(std::string("missing the ") + (!meta ? "metadata" : !table ? "table" : "gyro") +
                           " file; give one metadata, one table and one gyro file");
  return importTexts(paths[*meta] + ", " + paths[*table] + ", " + paths[*gyro], paths[*meta], texts[*meta],
                     paths[*table], texts[*table], paths[*gyro], texts[*gyro], options);
}

Status splitIntoSwingWindows(ImportedSession& imported, const std::vector<analysis::SwingWindow>& windows) {
  auto& points = imported.recording.testPoints;
  if (points.size() != 1 || points.front().kind != TestPointKind::kSwing)
    return invalidArgument("segmentation cuts one continuous swing recording (metadata with one test point); this one "
                           "holds " + std::to_string(points.size()) + " test points already");
  if (windows.empty()) return invalidArgument("no swing windows to cut the recording into");
  if (windows.size() > kMaxPlanPoints)  // as many test points as a plan may have
    return invalidArgument(std::to_string(windows.size()) + " swing windows; at most " +
                           std::to_string(kMaxPlanPoints) + " test points, as in a plan: import the recording in parts");
  const Axis axis = points.front().axis;
  auto cut = analysis::splitIntoWindows(points.front(), windows);
  for (const auto& tp : cut)
    if (tp.table.size() < 16 || tp.imu.size() < 16)
      return invalidArgument("the window of test point " + std::to_string(tp.index + 1) +
                             " holds too few samples; check the window times against the recording's time_s");
  TestPlan plan;
  plan.restBetweenS = imported.info.plan.restBetweenS;
  for (const auto& w : windows) {
    TestPoint p;
    p.axis = axis;
    p.frequencyHz = w.frequencyHz;
    p.amplitudeDeg = w.amplitudeDeg;
    p.durationS = w.endS - w.startS;
    plan.points.push_back(p);
  }
  imported.info.plan = plan;
  points = std::move(cut);
  return Status::ok();
}

}  // namespace fog::io
