#include "core/io/csv_export.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "core/analysis/channels.h"
#include "core/analysis/report_writer.h"
#include "core/analysis/sine_fit.h"
#include "core/io/metadata.h"

namespace fog::io {

namespace {

namespace fs = std::filesystem;

// Builds a file's text in memory (a 30-min session is ~100 MB of CSV at most)
// and writes it in one go.
class Text {
 public:
  Text& raw(std::string_view s) {
    out_.append(s);
    return *this;
  }
  Text& num(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out_.append(buf, r.ptr);
    return *this;
  }
  Text& integer(std::uint64_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out_.append(buf, r.ptr);
    return *this;
  }
  Text& comma() {
    out_.push_back(',');
    return *this;
  }
  Text& eol() {
    out_.push_back('\n');
    return *this;
  }
  const std::string& str() const { return out_; }
  void reserve(std::size_t n) { out_.reserve(n); }

 private:
  std::string out_;
};

Status writeFile(const fs::path& path, const std::string& text) {
  std::FILE* f = std::fopen(path.string().c_str(), "wb");
  if (!f) return ioError("cannot create " + path.string() + "; check that the directory is writable");
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const bool closed = std::fclose(f) == 0;
  if (!ok || !closed) return ioError("could not write all of " + path.string() + " (disk full?)");
  return Status::ok();
}

bool isExportFile(const std::string& name) {
  if (name == "metadata.json" || name == "table.csv" || name == "gyro.csv" || name == "fits.csv" ||
      name == "report.json" || name == "delays.csv")
    return true;
  const std::string prefix = "residuals_", suffix = ".csv";
  if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  for (std::size_t i = prefix.size(); i < name.size() - suffix.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

// Creates the directory or checks that it may be written into (see header).
Status prepareDirectory(const fs::path& dir, bool overwrite) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) return ioError(dir.string() + " exists and is not a directory");
  } else if (!fs::create_directories(dir, ec)) {
    return ioError("cannot create directory " + dir.string() + ": " + ec.message());
  }
  std::vector<fs::path> ours;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!overwrite)
      return invalidArgument(dir.string() + " is not empty (it holds " + name +
                             "); export into a new or empty directory, or allow overwriting a previous export");
    if (!isExportFile(name) || !entry.is_regular_file())
      return invalidArgument(dir.string() + " holds " + name +
                             ", which is not from a fogbench export; export into a new or empty directory");
    ours.push_back(entry.path());
  }
  if (ec) return ioError("cannot list " + dir.string() + ": " + ec.message());
  for (const auto& p : ours)
    if (!fs::remove(p, ec)) return ioError("cannot remove " + p.string() + " of the previous export: " + ec.message());
  return Status::ok();
}

std::string tableCsv(const Recording& rec) {
  Text t;
  std::size_t rows = 0;
  for (const auto& p : rec.testPoints) rows += p.table.size();
  t.reserve(rows * 80 + 256);
  t.raw("# fogbench table stream: angles (deg) stamped by the sampling board; docs/formats.md\n");
  t.raw("test_point,time_s,x_deg,y_deg,z_deg\n");
  for (const auto& p : rec.testPoints)
    for (const auto& s : p.table) {
      t.integer(static_cast<std::uint64_t>(p.index + 1)).comma().num(s.timeS);
      for (double a : s.angleDeg) t.comma().num(a);
      t.eol();
    }
  return t.str();
}

std::string gyroCsv(const Recording& rec) {
  Text t;
  std::size_t rows = 0;
  for (const auto& p : rec.testPoints) rows += p.imu.size();
  t.reserve(rows * 100 + 256);
  t.raw("# fogbench gyro stream: angle increments (deg) over the frame ending at time_s; docs/formats.md\n");
  t.raw("test_point,time_s,x_inc_deg,y_inc_deg,z_inc_deg,temperature_c,lost_before\n");
  for (const auto& p : rec.testPoints)
    for (const auto& s : p.imu) {
      t.integer(static_cast<std::uint64_t>(p.index + 1)).comma().num(s.timeS);
      // Degrees as recorded, so that they read back bit-identical.
      for (double d : s.incrementDeg) t.comma().num(d);
      t.comma().num(s.temperatureC).comma().integer(s.lostBefore).eol();
    }
  return t.str();
}

constexpr const char* kFitsHeader =
    "test_point,channel,model,frequency_hz,frequency_std_hz,period_ms,period_std_ms,phase_ms,phase_std_ms,"
    "amplitude_deg,amplitude_std_deg,offset_deg,trend_deg_per_s,trend_std_deg_per_s,residual_rms_deg,"
    "chi2_per_dof,samples,lag_ms,lag_std_ms,magnitude_ratio,magnitude_ratio_std\n";

void fitRow(Text& t, int index, const char* channel, const char* model, const analysis::SineFit& f, bool gyro) {
  t.integer(static_cast<std::uint64_t>(index + 1)).comma().raw(channel).comma().raw(model);
  t.comma().num(f.frequencyHz).comma().num(f.frequencyStdHz);
  t.comma().num(f.periodMs).comma().num(f.periodStdMs);
  t.comma().num(f.phaseMs).comma().num(f.phaseStdMs);
  t.comma().num(f.amplitudeDeg).comma().num(f.amplitudeStdDeg);
  t.comma().num(f.offsetDeg).comma();
  if (gyro) t.num(f.trendDegPerS).comma().num(f.trendStdDegPerS);
  else t.comma();
  t.comma().num(f.residualRmsDeg).comma().num(f.chiSquarePerDof).comma().integer(f.samples);
  t.raw(",,,,\n");  // lag and magnitude ratio: joint fit only
}

std::string fitsCsv(const analysis::DelayReport& report) {
  Text t;
  t.raw("# fogbench fits: angle = A sin(2 pi (t - t0) / T) + offset (+ trend t for the gyro); "
        "t0 = phase_ms; empty = not a parameter of that model; docs/formats.md\n");
  t.raw(kFitsHeader);
  for (const auto& p : report.points) {
    fitRow(t, p.index, "table", "3-parameter", p.tableNominal, false);
    fitRow(t, p.index, "gyro", "3-parameter", p.gyroNominal, true);
    fitRow(t, p.index, "table", "4-parameter", p.tableFit, false);
    fitRow(t, p.index, "gyro", "4-parameter", p.gyroFit, true);
    const auto& j = p.joint;
    const double periodMs = j.frequencyHz > 0.0 ? 1e3 / j.frequencyHz : 0.0;
    const double periodStdMs = j.frequencyHz > 0.0 ? 1e3 * j.frequencyStdHz / (j.frequencyHz * j.frequencyHz) : 0.0;
    t.integer(static_cast<std::uint64_t>(p.index + 1)).raw(",table+gyro,joint");
    t.comma().num(j.frequencyHz).comma().num(j.frequencyStdHz).comma().num(periodMs).comma().num(periodStdMs);
    t.raw(",,");  // the joint fit has a lag, not a phase per channel
    t.comma().num(std::hypot(j.a, j.b)).comma();  // table amplitude; no std from the joint fit
    t.comma().num(j.offsetDeg).comma().num(j.trendDegPerS).comma().num(j.trendStdDegPerS);
    t.raw(",").comma().num(j.chiSquarePerDof).comma().integer(p.tableSamples + p.imuSamples);
    t.comma().num(j.lagS * 1e3).comma().num(j.lagStdS * 1e3).comma().num(j.gain).comma().num(j.gainStd).eol();
  }
  return t.str();
}

Result<std::string> residualsCsv(const TestPointData& data, const analysis::TestPointResult& p) {
  FOG_ASSIGN_OR_RETURN(auto r, exportResiduals(data, p));
  Text t;
  t.reserve((r.tableTimeS.size() + r.gyroTimeS.size()) * 50 + 256);
  t.raw("# fogbench residuals of test point ").integer(static_cast<std::uint64_t>(p.index + 1));
  t.raw(", 4-parameter fits: table = angle - fit at time_s; gyro = increment - fitted increment over the frame "
        "ending at time_s; docs/formats.md\n");
  t.raw("channel,time_s,residual_deg\n");
  for (std::size_t i = 0; i < r.tableTimeS.size(); ++i)
    t.raw("table,").num(r.tableTimeS[i]).comma().num(r.tableResidualDeg[i]).eol();
  for (std::size_t i = 0; i < r.gyroTimeS.size(); ++i)
    t.raw("gyro,").num(r.gyroTimeS[i]).comma().num(r.gyroResidualDeg[i]).eol();
  return t.str();
}

}  // namespace

Result<ExportResiduals> exportResiduals(const TestPointData& data, const analysis::TestPointResult& p) {
  // The channels exactly as the analysis built them (with the gyro sign it
  // applied), so the residuals are those of the reported fits.
  FOG_ASSIGN_OR_RETURN(auto ch, analysis::makeChannels(data, p.gyroSign));
  const auto table = analysis::tableResiduals(ch.table, p.tableFit);
  const auto gyro = analysis::gyroIncrementResiduals(ch.gyro, p.gyroFit);
  ExportResiduals r;
  // Times as recorded (not re-added to the channel's reference, which would
  // round them): the channel holds the table samples with a finite time and
  // swing-axis angle, and every IMU frame but the first, in order.
  const auto axis = static_cast<std::size_t>(data.axis);
  std::size_t i = 0;
  for (const auto& s : data.table) {
    if (!std::isfinite(s.timeS) || !std::isfinite(s.angleDeg[axis])) continue;
    if (i == table.size()) break;
    r.tableTimeS.push_back(s.timeS);
    r.tableResidualDeg.push_back(table[i++]);
  }
  for (std::size_t k = 0; k < gyro.size() && k + 1 < data.imu.size(); ++k) {
    r.gyroTimeS.push_back(data.imu[k + 1].timeS);
    r.gyroResidualDeg.push_back(gyro[k]);
  }
  return r;
}

std::string formatDouble(double v) {
  Text t;
  t.num(v);
  return t.str();
}

Result<std::string> exportMetadataJson(const SessionInfo& info, const Recording& rec) {
  // The increments are in degrees (protocol::RecordingBuilder); the metadata
  // states the pulse equivalent they were made with.
  if (!(rec.pulseEquivalentDeg > 0.0))
    return invalidArgument("the recording states no gyro pulse equivalent (it holds no gyro samples); "
                           "there is nothing to export");
  detail::Metadata meta;
  meta.info = info;
  meta.info.bench.pulseEquivalentDeg = rec.pulseEquivalentDeg;
  meta.info.bench.counterHz = rec.counterHz;
  meta.info.bench.counterBits = rec.counterBits;
  meta.hasStream = true;
  meta.stream = rec.health;
  // One entry per test point of the plan or of the data, whichever reaches
  // further; the data's nominal values are the ones the analysis used.
  std::size_t count = info.plan.points.size();
  for (const auto& p : rec.testPoints) count = std::max(count, static_cast<std::size_t>(p.index) + 1);
  meta.testPoints.resize(count);
  for (std::size_t i = 0; i < info.plan.points.size(); ++i) {
    const TestPoint& tp = info.plan.points[i];
    auto& m = meta.testPoints[i];
    m.axis = tp.axis;
    m.frequencyHz = tp.frequencyHz;
    m.amplitudeDeg = tp.amplitudeDeg;
    m.hasPlan = true;
    m.durationS = tp.durationS;
    m.settleS = tp.settleS;
    m.startPhaseDeg = tp.startPhaseDeg;
    m.kind = tp.kind;
  }
  for (const auto& p : rec.testPoints) {
    if (p.index < 0) return invalidArgument("test point index " + std::to_string(p.index) + " is negative");
    auto& m = meta.testPoints[static_cast<std::size_t>(p.index)];
    m.axis = p.axis;
    m.frequencyHz = p.nominalFrequencyHz;
    m.amplitudeDeg = p.nominalAmplitudeDeg;
    if (p.kind == TestPointKind::kStatic) m.kind = TestPointKind::kStatic;
  }

  return detail::metadataToJson(meta);
}

Status exportCsv(const std::string& dirText, const SessionInfo& info, const Recording& rec,
                 const analysis::DelayReport* report, bool overwrite, const std::string& delaysCsv) {
  FOG_ASSIGN_OR_RETURN(auto metaJson, exportMetadataJson(info, rec));
  const fs::path dir(dirText);
  if (Status s = prepareDirectory(dir, overwrite); !s.isOk()) return s;
  if (Status s = writeFile(dir / "metadata.json", metaJson); !s.isOk()) return s;
  if (Status s = writeFile(dir / "table.csv", tableCsv(rec)); !s.isOk()) return s;
  if (Status s = writeFile(dir / "gyro.csv", gyroCsv(rec)); !s.isOk()) return s;
  if (!report) return Status::ok();

  if (Status s = writeFile(dir / "fits.csv", fitsCsv(*report)); !s.isOk()) return s;
  if (!delaysCsv.empty())
    if (Status s = writeFile(dir / "delays.csv", delaysCsv); !s.isOk()) return s;
  for (const auto& p : report->points) {
    const TestPointData* data = nullptr;
    for (const auto& tp : rec.testPoints)
      if (tp.index == p.index) data = &tp;
    if (!data)
      return invalidArgument("the report has test point " + std::to_string(p.index + 1) +
                             ", which the recording does not; export the report with its own recording");
    FOG_ASSIGN_OR_RETURN(auto text, residualsCsv(*data, p));
    if (Status s = writeFile(dir / ("residuals_" + std::to_string(p.index + 1) + ".csv"), text); !s.isOk()) return s;
  }
  analysis::ReportContext context;
  context.source = info.source;
  return writeFile(dir / "report.json", analysis::formatReportJson(*report, context));
}

}  // namespace fog::io
