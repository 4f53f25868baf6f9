#pragma once
// The calibration report: a signed-off record of one session's IMU delay
// measurement, as a PDF (A4 portrait) or as page images (for previews and
// tests) drawn by the same code.
//
// Pages: (1) identity, verdict, results summary, signatures; (2) bench
// constants, test plan, stream health, the paper's delay budget beside the
// measurement; for an axis with three or more passed test points (a frequency
// response plan) its frequency response: the Bode plot, the points and the
// fitted models; then per analysed test point (3) the table and gyro angles with
// their fitted sinusoids and the residuals of both fits, (4) the fit table,
// the delay breakdown with uncertainties and Cramer-Rao bound, the per-period
// lag track and the test point's verdict. Every page carries a header with
// the IMU's identity and a footer with the session, the raw data hash and
// "page n of N".
//
// The verdict of a stored result is printed as stored (its word, reasons and
// limit: ReportInput::stored), never re-judged; an incomplete run's verdict
// is INCOMPLETE, whatever its data give.
//
// Acceptance rule (analysis/verdict.h): a test point is INVALID when a
// validity check failed; otherwise it PASSES when IMU delay + k sigma < limit
// (one-sided guarded acceptance, k the result's stored coverage factor, 2 by
// default) and FAILS if not. The session passes when every test point of the
// plan gave a delay and every one passes. The first page states this
// decision rule with its k and maximum false-accept risk, and the results
// table each vouched point's own risk (analysis/decision_rule.h; ISO/IEC
// 17025:2017 §7.8.6).
//
// Needs a QApplication (the plots are Qwt widgets); any platform works,
// including offscreen. Not thread-safe: call from the GUI thread.

#include <QImage>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/session/stored_result.h"
#include "core/analysis/delay_analysis.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

namespace fog::report {

struct ReportInput {
  SessionInfo info;
  Recording recording;  // the decoded data the delays were computed from (plotted)
  analysis::DelayReport delays;
  // The raw sampling-board byte stream, hashed onto the report. Empty for
  // imported data: the report then says "no raw stream (imported)".
  std::vector<std::uint8_t> rawBytes;
  double imuDelayLimitMs = 0.8;
  // The decision rule's coverage factor k (a stored record's own k wins).
  double coverageK = analysis::kDefaultCoverageFactor;
  // Which of the session's stored results the report shows, in words
  // (when it was stored, by which version, with which constants); the
  // report prints it on its first page. Empty: computed for the report
  // (fogbench-cli report), with the constants it shows.
  QString resultShown;
  // The stored result the report shows: its verdict, reasons and limit are
  // printed as stored (imuDelayLimitMs is then the record's). Unset: a
  // report of data no result was stored for, judged here with
  // imuDelayLimitMs.
  std::optional<session::StoredResultRecord> stored;
  // Unset `stored` only: why the run stopped early ("" for a complete run);
  // the verdict is then INCOMPLETE.
  std::string incompleteReason;
  // The session's stored results, oldest first: its audit trail, printed
  // under "Analyses of this session" (one line each, as
  // session::auditTrailLines has them, in the report's language). Empty for
  // data without a session (a preset, a raw stream) or without results.
  std::vector<session::StoredResultRecord> analyses;
};

// The one place a report's input is put together (fogbench-cli report, the
// GUI's Results view), from the result shown (session::showResult, or a
// run's own analysis): with a stored record, its verdict and limit are the
// report's; without one, `limitMs` judges and `incompleteReason` (an
// incomplete run) makes the verdict INCOMPLETE. `resultShown` as in
// ReportInput.
ReportInput makeReportInput(SessionInfo info, Recording recording, analysis::DelayReport delays,
                            std::vector<std::uint8_t> rawBytes, const session::StoredResultRecord* stored,
                            double limitMs, const std::string& incompleteReason, QString resultShown,
                            double coverageK = analysis::kDefaultCoverageFactor);

// SHA-256 of the bytes, 64 lower-case hex digits; empty for no bytes.
QString rawDataSha256(const std::vector<std::uint8_t>& bytes);

// The verdict of the report (the core's rule, analysis/verdict.h) in the
// report's words. A point's line, e.g.
// "PASS: IMU delay 0.5158 ± 0.0015 ms; + 2σ = 0.5188 ms < 0.8 ms limit (margin 0.2812 ms)",
// or "INVALID: " with the failed validity checks.
struct PointVerdict {
  int index = 0;  // test point index (0-based)
  bool pass = false;
  bool vouched = false;  // its delay may be printed bare (PASS or FAIL)
  QString word;  // "PASS", "FAIL", "INVALID", "INCOMPLETE" or "NO VERDICT"
  QString line;
  // Vouched points only (else NaN): P(true delay >= limit | delay, sigma)
  // and the guard band k sigma (ms).
  double falseAcceptProbability = std::numeric_limits<double>::quiet_NaN();
  double guardBandMs = std::numeric_limits<double>::quiet_NaN();
};
struct Verdict {
  bool pass = false;
  QString word;      // "PASS", "FAIL", "INVALID" or "INCOMPLETE"
  QString headline;  // the word and the reason in a few words
  std::vector<PointVerdict> points;  // one per analysed test point, report order
  double limitMs = 0.8;
  double coverageK = analysis::kDefaultCoverageFactor;  // the shown (stored) rule's k
  QString ruleProvenance;  // "" or why k is not stored (a row stored before k was)
};
Verdict calibrationVerdict(const analysis::DelayReport& delays, double imuDelayLimitMs);
// The verdict the report of `in` prints: the stored record's when there is
// one (points in delays' order, matched by index), else judged as above;
// INCOMPLETE for an incomplete run. When this version's analysis (in.delays)
// differs from the stored record the headline says so.
Verdict calibrationVerdict(const ReportInput& in);

// Checks what the drawing needs: a finite limit > 0, and recording data for
// every analysed test point.
Status checkReportInput(const ReportInput& in);

// Writes the report as a PDF. Fails with a one-line reason (unwritable path,
// bad input).
Status writeCalibrationPdf(const ReportInput& in, const QString& pdfPath);

// The same pages as images at `dpi` (white background). When drawnText is
// given, every string drawn on the pages (outside the plots) is appended to
// it, in drawing order: what a reader of the page sees, for tests.
Result<std::vector<QImage>> renderCalibrationPages(const ReportInput& in, int dpi,
                                                   QStringList* drawnText = nullptr);

}  // namespace fog::report
