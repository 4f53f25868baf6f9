#include "core/session/shown_csv.h"

#include "core/io/csv_export.h"

namespace fog::session {

namespace {

std::string num(double v) { return io::formatDouble(v); }

}  // namespace

std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::string csvField(const std::string& text) {
  const std::string s = oneLine(text);
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csvTextField(const std::string& text) {
  const bool formula = !text.empty() && std::string("=+-@\t\r").find(text.front()) != std::string::npos;
  return csvField(formula ? "'" + text : text);
}

std::string delayBreakdownCsv(const analysis::DelayReport& report, const ShownVerdict& verdict,
                              const std::string& source) {
  std::string t = "# fogbench delay breakdown: measured lag + table read delay = IMU delay; "
                  "IMU delay - processing board delay = gyro's own delay; 1 sigma; ms\n";
  t += "# source: " + oneLine(source) + "\n";
  t += std::string("# result verdict: ") + shownVerdictWord(verdict.verdict) + " (" +
       (verdict.stored ? "stored" : "not stored") + ", limit " + num(verdict.limitMs) +
       " ms); a point whose verdict is not pass or fail has its delays refused (vouched false)\n";
  t += "test_point,axis,frequency_hz,quantity,value_ms,std_ms,verdict,vouched,reason\n";
  const auto& c = report.constants;
  for (const auto& p : report.points) {
    ShownPoint shown;  // a point the verdict does not state: refused
    if (const auto* sp = verdict.point(p.index)) shown = *sp;
    const std::string head =
        std::to_string(p.index + 1) + "," + axisLabel(p.axis) + "," + num(p.nominalFrequencyHz) + ",";
    std::string reason;
    for (const auto& r : shown.reasons) reason += (reason.empty() ? "" : "; ") + r;
    const std::string tail = std::string(",") + shownVerdictName(shown.verdict) + "," +
                             (shown.vouched() ? "true" : "false") + "," + csvField(reason);
    auto row = [&](const char* quantity, double value, double std) {
      t += head + quantity + "," + num(value) + "," + num(std) + tail + "\n";
    };
    row("measured_lag", p.lagMs, p.lagStdMs);
    row("table_read_delay", c.tableReadDelayMs, c.tableReadDelayStdMs);
    row("imu_delay", p.imuDelayMs, p.imuDelayStdMs);
    row("processing_board_delay", c.boardDelayMs, c.boardDelayStdMs);
    row("gyro_delay", p.gyroDelayMs, p.gyroDelayStdMs);
  }
  return t;
}

}  // namespace fog::session
