#include "ui/report/calibration_report.h"

#include <QApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QFileInfo>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <qwt_plot.h>

#include "core/common/gyro_signs.h"
#include "core/analysis/theory.h"
#include "core/analysis/uncertainty_bound.h"
#include "core/analysis/verdict.h"
#include "core/common/version.h"
#include "core/noise/gyro_noise.h"
#include "ui/core_text.h"
#include "ui/verdict_text.h"
#include "ui/plot_data/allan_curves.h"
#include "ui/plot_data/bode_curves.h"
#include "ui/report/page_flow.h"
#include "ui/report/report_plots.h"
#include "ui/plot_data/test_point_traces.h"

namespace fog::report {

using analysis::DelayReport;
using analysis::SineFit;
using analysis::TestPointResult;
using detail::PageFlow;
using ui::coreText;
using detail::Table;

namespace {

const QColor kTableData(120, 170, 215);
const QColor kTableFit(8, 48, 107);
const QColor kGyroData(250, 175, 110);
const QColor kGyroFit(165, 15, 21);
const QColor kPassColour(20, 110, 40);
const QColor kFailColour(180, 20, 20);
const QColor kMuted(90, 90, 90);


// ---- numbers -------------------------------------------------------------

QString fixed(double v, int decimals) { return QString::number(v, 'f', decimals); }

// An uncertainty to two significant digits without an exponent: 0.00051, 0.88, 12.
QString plain2(double v) {
  if (!(v > 0.0)) return "0";
  return fixed(v, std::clamp(1 - static_cast<int>(std::floor(std::log10(v))), 0, 9));
}

// Decimals (ms) that show an uncertainty to two significant digits and never
// fewer than the paper's four: 0.0015 -> 4, 0.00010 -> 5 (as the text report).
int decimalsFor(double stdMs) {
  if (!(stdMs > 0.0)) return 4;
  return std::clamp(1 - static_cast<int>(std::floor(std::log10(stdMs))), 4, 7);
}

QString valueWithStd(double v, double sd, int decimals) { return fixed(v, decimals) + " ± " + fixed(sd, decimals); }

QString limitText(double limitMs) { return QString::number(limitMs, 'g', 6); }

QString orNotRecorded(const std::string& s) {
  return s.empty() ? QObject::tr("not recorded") : QString::fromStdString(s);
}

QString axisUpper(Axis a) { return QString(axisName(a)).toUpper(); }

// Two short lines, for narrow table cells.
QString shortCondition(const TestPointResult& p) {
  return QObject::tr("%1 axis\n%2 Hz / %3°, %4 s")
      .arg(axisUpper(p.axis))
      .arg(p.nominalFrequencyHz)
      .arg(fixed(p.tableFit.amplitudeDeg, 2))
      .arg(fixed(p.durationS, 0));
}

QString condition(const TestPointResult& p) {
  return QObject::tr("%1 axis, %2 Hz / %3°, %4 s")
      .arg(axisUpper(p.axis))
      .arg(p.nominalFrequencyHz)
      .arg(fixed(p.tableFit.amplitudeDeg, 3))
      .arg(fixed(p.durationS, 1));
}

// ---- page targets --------------------------------------------------------

constexpr double kMmPerInch = 25.4;

class PdfTarget : public detail::PageTarget {
 public:
  explicit PdfTarget(const QString& path) : writer_(path) {
    writer_.setPageSize(QPageSize(QPageSize::A4));
    writer_.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
    writer_.setResolution(600);
    writer_.setCreator(QStringLiteral("fogbench " FOG_VERSION));
  }
  void setTitle(const QString& t) { writer_.setTitle(t); }
  bool open() {
    opened_ = painter_.begin(&writer_);
    return opened_;
  }
  void close() {
    if (painter_.isActive()) painter_.end();
  }
  const QPaintDevice* metricsDevice() const override { return &writer_; }
  double dotsPerMm() const override { return writer_.resolution() / kMmPerInch; }
  QPainter* beginPage() override {
    if (pages_++ > 0) writer_.newPage();
    painter_.setRenderHint(QPainter::Antialiasing, true);
    return &painter_;
  }
  void endPage() override {}

 private:
  QPdfWriter writer_;
  QPainter painter_;
  bool opened_ = false;
  int pages_ = 0;
};

class ImageTarget : public detail::PageTarget {
 public:
  explicit ImageTarget(int dpi) : dpi_(dpi), metrics_(1, 1, QImage::Format_RGB32) { setDpi(metrics_); }
  const QPaintDevice* metricsDevice() const override { return &metrics_; }
  double dotsPerMm() const override { return dpi_ / kMmPerInch; }
  QPainter* beginPage() override {
    const auto w = static_cast<int>(std::lround(PageFlow::kPageWidthMm * dotsPerMm()));
    const auto h = static_cast<int>(std::lround(PageFlow::kPageHeightMm * dotsPerMm()));
    pages_.emplace_back(w, h, QImage::Format_RGB32);
    setDpi(pages_.back());
    pages_.back().fill(Qt::white);
    painter_.begin(&pages_.back());  // ended before the vector can grow again
    painter_.setRenderHint(QPainter::Antialiasing, true);
    painter_.setRenderHint(QPainter::TextAntialiasing, true);
    return &painter_;
  }
  void endPage() override {
    if (painter_.isActive()) painter_.end();
  }
  std::vector<QImage> take() { return std::move(pages_); }

 private:
  void setDpi(QImage& image) const {
    const int dpm = static_cast<int>(std::lround(dpi_ / 0.0254));
    image.setDotsPerMeterX(dpm);
    image.setDotsPerMeterY(dpm);
  }
  int dpi_;
  QImage metrics_;
  std::vector<QImage> pages_;
  QPainter painter_;
};

// Measures with another target's device, draws nothing.
class MeasureTarget : public detail::PageTarget {
 public:
  explicit MeasureTarget(const detail::PageTarget& real) : real_(real) {}
  const QPaintDevice* metricsDevice() const override { return real_.metricsDevice(); }
  double dotsPerMm() const override { return real_.dotsPerMm(); }
  QPainter* beginPage() override { return nullptr; }
  void endPage() override {}

 private:
  const detail::PageTarget& real_;
};

// ---- content -------------------------------------------------------------

struct Content {
  const ReportInput& in;
  Verdict verdict;
  QString hash;                                // empty: no raw stream
  std::vector<ui::TestPointTraces> traces;     // one per analysed test point
  QString producedUtc;
  std::vector<noise::GyroNoiseReport> noise;   // one per static segment
  std::vector<analysis::ResponseAnalysis> responses;  // per axis with two or more passed points
};

// Data the bench's simulator made (a run on it, or an import or replay of
// such a run): every page says so, so that no simulated report passes for
// the calibration of a real IMU.
bool simulatedData(const SessionInfo& info) {
  return QString::fromStdString(info.source).contains(QStringLiteral("simulator"), Qt::CaseInsensitive);
}

QString simulatedBanner() { return QObject::tr("SIMULATED DATA — not a measurement of a real IMU"); }

void decorate(PageFlow& flow, const Content& c, int page, int pageCount) {
  const double left = PageFlow::kLeftMm, width = PageFlow::kContentWidthMm;
  const QFont small = PageFlow::font(7.5);
  const auto& info = c.in.info;
  if (simulatedData(info))
    flow.text(QRectF(left, 16.2, width, 4.5), Qt::AlignHCenter | Qt::AlignVCenter, simulatedBanner(),
              PageFlow::font(8.0, true), kFailColour);
  const QString imu = QObject::tr("IMU %1 · S/N %2").arg(orNotRecorded(info.imuModel), orNotRecorded(info.imuSerial));
  flow.text(QRectF(left, 10.0, width, 5.0), Qt::AlignLeft | Qt::AlignBottom,
            QObject::tr("fogbench · IMU delay calibration report"), small, kMuted);
  flow.text(QRectF(left, 10.0, width, 5.0), Qt::AlignRight | Qt::AlignBottom, imu, small, kMuted);
  flow.line(left, 15.5, left + width, 15.5, kMuted, 0.2);

  const double footer = PageFlow::kPageHeightMm - 14.0;
  flow.line(left, footer, left + width, footer, kMuted, 0.2);
  const QString session =
      QObject::tr("Session %1 · raw data %2 · fogbench %3")
          .arg(info.createdUtc.empty() ? QObject::tr("(date not recorded)") : QString::fromStdString(info.createdUtc),
               c.hash.isEmpty() ? QObject::tr("not hashed (imported)") : "SHA-256 " + c.hash.left(16) + "…",
               QStringLiteral(FOG_VERSION));
  flow.text(QRectF(left, footer + 1.0, width, 5.0), Qt::AlignLeft | Qt::AlignTop, session, small, kMuted);
  if (pageCount > 0)
    flow.text(QRectF(left, footer + 1.0, width, 5.0), Qt::AlignRight | Qt::AlignTop,
              QObject::tr("Page %1 of %2").arg(page).arg(pageCount), small, kMuted);
}

QString rawDataText(const Content& c) {
  if (c.in.rawBytes.empty()) return QObject::tr("no raw stream (imported)");
  QString digits = QString::number(static_cast<qulonglong>(c.in.rawBytes.size()));
  for (auto i = digits.size() - 3; i > 0; i -= 3) digits.insert(i, QChar(0x2009));  // thin space between groups
  return QObject::tr("%1 bytes of sampling-board stream").arg(digits);
}

// The decision rule and its risk (ISO/IEC 17025:2017 §7.8.6): the shown
// result's k and limit, never today's default.
QString decisionRuleParagraph(const Verdict& v) {
  QString s =
      QObject::tr("Decision rule (ISO/IEC 17025:2017 §7.8.6; ILAC-G8:09/2019 guarded acceptance, one-sided): a test "
                  "point is invalid when a validity check fails (reversed gyro axis, clock-rate mismatch, a swing "
                  "that is not a steady sinusoid, a negative IMU delay); otherwise it passes when its IMU delay plus "
                  "k = %1 standard uncertainties (1σ, including the bench constants; guard band kσ) is below the "
                  "limit of %2 ms, and fails if not; the session passes when every test point of the plan gave a "
                  "delay and passes. Maximum probability of false accept 1 − Φ(k) = %3: a delay measured just at "
                  "the acceptance boundary, with a Gaussian error of the stated σ.")
          .arg(QString::fromStdString(analysis::coverageFactorText(v.coverageK)), limitText(v.limitMs),
               QString::fromStdString(analysis::probabilityText(analysis::maxFalseAcceptProbability(v.coverageK))));
  if (!v.ruleProvenance.isEmpty()) s += " " + QObject::tr("k %1.").arg(coreText(v.ruleProvenance.toStdString()));
  return s;
}

// A point's own risk for the results table: vouched points only (the
// verdict beside it and the note under the table say why not).
QString pointRiskText(const PointVerdict& p) {
  if (!p.vouched || !std::isfinite(p.falseAcceptProbability)) return QObject::tr("— refused");
  return QString::fromStdString(analysis::probabilityText(p.falseAcceptProbability));
}

void verdictBox(PageFlow& flow, const Content& c) {
  const double left = PageFlow::kLeftMm, width = PageFlow::kContentWidthMm;
  const double wordWidth = 36.0, pad = 3.0;
  const double textWidth = width - wordWidth - 2 * pad;
  const QFont word = PageFlow::font(24.0, true), head = PageFlow::font(9.5, true), body = PageFlow::font(8.5);
  const QColor colour = c.verdict.pass ? kPassColour : kFailColour;

  QStringList lines;
  for (const auto& p : c.verdict.points) {
    const auto& r = *std::find_if(c.in.delays.points.begin(), c.in.delays.points.end(),
                                  [&](const TestPointResult& t) { return t.index == p.index; });
    lines << QObject::tr("Test point %1 (%2): %3").arg(p.index + 1).arg(condition(r), p.line);
  }
  for (const auto& f : c.in.delays.failedPoints)
    lines << QObject::tr("INVALID: no delay from %1").arg(coreText(f));
  const QString rule = decisionRuleParagraph(c.verdict);

  const QString& headline = c.verdict.headline;
  double h = flow.textHeightMm(headline, head, textWidth) + 1.5;
  for (const auto& l : lines) h += flow.textHeightMm(l, body, textWidth) + 1.0;
  h += flow.textHeightMm(rule, PageFlow::font(7.5), textWidth);
  h = std::max(h + 2 * pad, 22.0);

  flow.ensureSpace(h);
  const double top = flow.y();
  flow.rect(QRectF(left, top, width, h), colour, c.verdict.pass ? QColor(235, 246, 236) : QColor(252, 235, 235), 0.6);
  flow.text(QRectF(left, top, wordWidth, h), Qt::AlignCenter, c.verdict.word, word, colour);
  double y = top + pad;
  const double x = left + wordWidth + pad;
  auto put = [&](const QString& s, const QFont& f, const QColor& col, double after) {
    const double th = flow.textHeightMm(s, f, textWidth);
    flow.text(QRectF(x, y, textWidth, th), Qt::AlignLeft | Qt::TextWordWrap, s, f, col);
    y += th + after;
  };
  put(headline, head, colour, 1.5);
  for (const auto& l : lines) put(l, body, Qt::black, 1.0);
  put(rule, PageFlow::font(7.5), kMuted, 0.0);
  flow.space(h + 3.0);
}

void signatureBlock(PageFlow& flow) {
  const double left = PageFlow::kLeftMm, width = PageFlow::kContentWidthMm;
  const QFont f = PageFlow::font(8.5);
  flow.ensureSpace(30.0);
  const double half = width / 2.0;
  for (int col = 0; col < 2; ++col) {
    const double x = left + col * half;
    const QString role = col == 0 ? QObject::tr("Tested by") : QObject::tr("Reviewed and approved by");
    flow.text(QRectF(x, flow.y(), half - 6.0, 5.0), Qt::AlignLeft, role, PageFlow::font(8.5, true));
    const double sy = flow.y() + 14.0;
    flow.line(x, sy, x + half - 8.0, sy, Qt::black, 0.2);
    flow.text(QRectF(x, sy + 0.8, half - 8.0, 5.0), Qt::AlignLeft, QObject::tr("Name, signature"), f, kMuted);
    const double dy = sy + 10.0;
    flow.line(x, dy, x + half - 8.0, dy, Qt::black, 0.2);
    flow.text(QRectF(x, dy + 0.8, half - 8.0, 5.0), Qt::AlignLeft, QObject::tr("Date"), f, kMuted);
  }
  flow.space(30.0);
}

void firstPage(PageFlow& flow, const Content& c) {
  const auto& info = c.in.info;
  const auto& d = c.in.delays;
  const double left = PageFlow::kLeftMm, width = PageFlow::kContentWidthMm;
  const QFont title = PageFlow::font(20.0, true);
  flow.text(QRectF(left, flow.y(), width, 10.0), Qt::AlignLeft | Qt::AlignVCenter,
            QObject::tr("IMU delay calibration report"), title, QColor(20, 40, 90));
  flow.space(11.0);
  flow.text(QRectF(left, flow.y(), width, 6.0), Qt::AlignLeft | Qt::AlignVCenter,
            QObject::tr("%1, serial number %2").arg(orNotRecorded(info.imuModel), orNotRecorded(info.imuSerial)),
            PageFlow::font(12.0), Qt::black);
  flow.space(9.0);
  if (simulatedData(info)) {
    flow.text(QRectF(left, flow.y(), width, 6.0), Qt::AlignLeft | Qt::AlignVCenter,
              simulatedBanner(), PageFlow::font(10.0, true), kFailColour);
    flow.space(8.0);
  }
  verdictBox(flow, c);

  flow.heading(QObject::tr("Session"));
  flow.keyValues(
      {
          {QObject::tr("IMU model"), orNotRecorded(info.imuModel)},
          {QObject::tr("IMU serial number"), orNotRecorded(info.imuSerial)},
          {QObject::tr("Lot"), orNotRecorded(info.lot)},
          {QObject::tr("Bench id"), orNotRecorded(info.benchId)},
          {QObject::tr("Operator"), orNotRecorded(info.operatorName)},
          {QObject::tr("Recorded (UTC)"), orNotRecorded(info.createdUtc)},
          {QObject::tr("Data source"), info.source.empty() ? orNotRecorded(info.source) : coreText(info.source)},
          {QObject::tr("Recorded with"),
           info.softwareVersion.empty() ? QObject::tr("not recorded")
                                        : "fogbench " + QString::fromStdString(info.softwareVersion)},
          {QObject::tr("Result reported"),
           c.in.resultShown.isEmpty()
               ? QObject::tr("computed when this report was produced, with the constants on page 2")
               : coreText(c.in.resultShown)},
          {QObject::tr("Report produced"), QObject::tr("%1 by fogbench %2").arg(c.producedUtc, QStringLiteral(FOG_VERSION))},
          {QObject::tr("Raw data"), rawDataText(c)},
          {QObject::tr("Raw data SHA-256"), c.hash.isEmpty() ? QObject::tr("none: no raw stream (imported)") : c.hash},
          {QObject::tr("Notes"), info.notes.empty() ? QObject::tr("none") : QString::fromStdString(info.notes)},
      },
      38.0, {9});  // the SHA-256 in a monospace face, to be copied and checked

  flow.heading(QObject::tr("Results"));
  Table t;
  // 174 mm, the content width, with the risk column beside the verdict.
  t.columns = {{"#", 5, Qt::AlignLeft},
               {QObject::tr("condition"), 29, Qt::AlignLeft},
               {QObject::tr("lag ± 1σ (ms)"), 26, Qt::AlignRight},
               {QObject::tr("CRLB (ms)"), 17, Qt::AlignRight},
               {QObject::tr("IMU delay ± 1σ (ms)"), 27, Qt::AlignRight},
               {QObject::tr("gyro delay ± 1σ (ms)"), 27, Qt::AlignRight},
               {QObject::tr("P(false accept)"), 22, Qt::AlignRight},
               {QObject::tr("verdict"), 21, Qt::AlignHCenter}};
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const auto& p = d.points[i];
    const int dec = decimalsFor(p.lagStdMs);
    t.rows.push_back({QString::number(p.index + 1), shortCondition(p), valueWithStd(p.lagMs, p.lagStdMs, dec),
                      fixed(p.crlbMs, dec),
                      valueWithStd(p.imuDelayMs, p.imuDelayStdMs, dec),
                      valueWithStd(p.gyroDelayMs, p.gyroDelayStdMs, dec),
                      pointRiskText(c.verdict.points[i]), c.verdict.points[i].word});
  }
  flow.table(t);
  for (const auto& f : d.failedPoints)
    flow.paragraph(QObject::tr("No delay from %1").arg(coreText(f)), PageFlow::font(8.5), kFailColour);
  for (const auto& cc : d.consistency) {
    const int dec = decimalsFor(cc.weightedLagStdMs);
    flow.paragraph(QObject::tr("Delay against frequency, %1 axis (%2 frequencies): weighted lag %3 ms, χ² %4 on %5 "
                               "dof, p = %6: %7.")
                       .arg(axisUpper(cc.axis))
                       .arg(cc.points)
                       .arg(valueWithStd(cc.weightedLagMs, cc.weightedLagStdMs, dec))
                       .arg(fixed(cc.chiSquare, 2))
                       .arg(cc.dof)
                       .arg(fixed(cc.pValue, 3))
                       .arg(cc.consistentWithPureDelay ? QObject::tr("consistent with a pure delay")
                                                       : QObject::tr("NOT a pure delay (frequency-dependent)")) +
                       (cc.leftOutPoints > 0
                            ? QObject::tr(" %1 refused test point(s) left out: their checks failed.").arg(cc.leftOutPoints)
                            : QString()),
                   PageFlow::font(8.5));
  }
  flow.paragraph(QObject::tr("Lag: gyro output behind the stamped table angle (joint fit). IMU delay = lag + table "
                             "read delay; gyro delay = IMU delay − processing-board delay. CRLB: Cramér–Rao bound "
                             "on the lag for the noise measured in this session. P(false accept): the probability "
                             "that the true IMU delay is at or above the limit, 1 − Φ((limit − delay)/σ), for a "
                             "Gaussian error of the stated σ; none for a refused (INVALID or INCOMPLETE) delay."),
                 PageFlow::font(7.5), kMuted);

  flow.heading(QObject::tr("Sign-off"));
  signatureBlock(flow);
}

// The paper's theoretical delay budget beside the measured delays (each
// marked refused where the verdict does not vouch for it); not for an
// imported recording, made on another bench.
void budgetSection(PageFlow& flow, const Content& c, bool imported) {
  const auto& d = c.in.delays;
  const auto& k = d.constants;
  if (imported) {
    // The paper's budget describes its FOG and board; an imported recording's
    // IMU and bench are other ones, so the budget is not set beside it.
    flow.heading(QObject::tr("Delay budget"));
    flow.paragraph(QObject::tr("Not shown: the paper's theoretical budget describes its own gyro and processing "
                               "board, and this recording was made on another bench (imported)."),
                   PageFlow::font(8.5), kMuted);
  } else {
    flow.heading(QObject::tr("Delay budget: the paper's theory beside the measurement"));
    const analysis::TheoryInputs theoryIn;
    const auto budget = analysis::delayBudget(theoryIn);
    auto range = [](double lo, double hi) { return lo == hi ? fixed(lo, 4) : fixed(lo, 4) + " – " + fixed(hi, 4); };
    // A delay the verdict does not vouch for keeps its mark here too.
    auto measured = [&](auto value, auto sd) {
      QStringList s;
      for (const auto& p : d.points) {
        const auto pv = std::find_if(c.verdict.points.begin(), c.verdict.points.end(),
                                     [&](const PointVerdict& x) { return x.index == p.index; });
        const QString number = valueWithStd(value(p), sd(p), decimalsFor(sd(p)));
        s << (pv != c.verdict.points.end() && pv->vouched
                  ? QObject::tr("#%1: %2").arg(p.index + 1).arg(number)
                  : QObject::tr("#%1: refused (%2, %3)")
                        .arg(p.index + 1)
                        .arg(number, pv != c.verdict.points.end() ? pv->word : ui::verdictWord(session::ShownVerdictKind::kNone)));
      }
      return s.join("\n");
    };
    Table theory;
    theory.columns = {{QObject::tr("stage"), 50, Qt::AlignLeft},
                      {QObject::tr("theory (ms)"), 30, Qt::AlignRight},
                      {QObject::tr("basis"), 48, Qt::AlignLeft},
                      {QObject::tr("measured (ms)"), 46, Qt::AlignRight}};
    double gyroMin = 0.0, gyroMax = 0.0;
    for (const auto& l : budget.lines) {
      theory.rows.push_back({coreText(l.stage), range(l.minMs, l.maxMs), coreText(l.basis), ""});
      theory.boldRows.push_back(false);
      if (l.stage.rfind("board:", 0) != 0) {
        gyroMin += l.minMs;
        gyroMax += l.maxMs;
      }
    }
    theory.rows.push_back({QObject::tr("gyro's own delay"), range(gyroMin, gyroMax),
                           QObject::tr("sensing, loop and pulse update"),
                           measured([](const TestPointResult& p) { return p.gyroDelayMs; },
                                    [](const TestPointResult& p) { return p.gyroDelayStdMs; })});
    theory.rows.push_back({QObject::tr("processing board"), range(budget.totalMinMs - gyroMin, budget.boardMaxMs),
                           QObject::tr("sampling, compensation, serial"),
                           QObject::tr("%1 (bench constant)").arg(fixed(k.boardDelayMs, 4))});
    theory.rows.push_back({QObject::tr("IMU delay (total)"), range(budget.totalMinMs, budget.totalMaxMs),
                           QObject::tr("the paper: < 0.8 ms"),
                           measured([](const TestPointResult& p) { return p.imuDelayMs; },
                                    [](const TestPointResult& p) { return p.imuDelayStdMs; })});
    theory.boldRows.insert(theory.boldRows.end(), {true, true, true});
    flow.table(theory);
    flow.paragraph(QObject::tr("Theory with the paper's figures: %1 m of fibre (eigen period %2 µs), loop delay ≤ %3 "
                               "eigen periods, pulse output updated every %4 ms, %5 MHz board clock, %6-byte frames at "
                               "%7 Mbaud.")
                       .arg(theoryIn.fibreLengthM)
                       .arg(fixed(budget.eigenPeriodUs, 2))
                       .arg(theoryIn.loopDelayEigenPeriods)
                       .arg(theoryIn.pulseUpdatePeriodS * 1e3)
                       .arg(theoryIn.boardClockHz / 1e6)
                       .arg(theoryIn.frameBytes)
                       .arg(theoryIn.baud / 1e6),
                   PageFlow::font(7.5), kMuted);
  }
}

// One stored result of the audit trail in the report's language (the
// words of session::auditTrailLines): who, tool and command line are data,
// shown as stored; the verdict is the record's, never re-judged.
QString auditLine(int number, const session::StoredResultRecord& r) {
  const QString when = r.createdUtc.empty() ? QObject::tr("(no time)") : QString::fromStdString(r.createdUtc);
  if (!r.usable)
    return QObject::tr("#%1 %2 · cannot be read: %3").arg(number).arg(when, coreText(r.problem));
  QString by;
  if (r.audit) {
    const auto& a = *r.audit;
    const QString whoSource = a.whoSource == "operator" ? QObject::tr("operator")
                              : a.whoSource == "login"  ? QObject::tr("login name")
                                                        : QString::fromStdString(a.whoSource);
    // The tools fogbench names itself, in the report's language.
    const std::string toolName = a.tool.empty() ? r.analysedBy : a.tool;
    const QString tool = toolName == "acquisition"            ? QObject::tr("recording run")
                         : toolName == "fogbench-cli analyze" ? QObject::tr("command-line analysis")
                         : toolName == "fogbench GUI Results" ? QObject::tr("GUI Results view")
                                                              : QString::fromStdString(toolName);
    by = QObject::tr("by %1 (%2) · %3").arg(QString::fromStdString(a.who), whoSource, tool);
    if (!a.command.empty()) by += " [" + QString::fromStdString(a.command) + "]";
  } else {
    by = QObject::tr("who and with what: not recorded (stored before the audit trail)");
  }
  const auto& k = r.constants;
  QString constants = QObject::tr("table read delay %1 ± %2 ms, board delay %3 ± %4 ms, limit %5 ms")
                          .arg(fixed(k.tableReadDelayMs, 3), fixed(k.tableReadDelayStdMs, 3),
                               fixed(k.boardDelayMs, 3), fixed(k.boardDelayStdMs, 3), fixed(r.imuDelayLimitMs, 3));
  if (k.gyroSign != std::array<int, kAxisCount>{1, 1, 1})
    constants += ", " + QObject::tr("gyro signs %1").arg(QString("x%1 y%2 z%3")
                                                             .arg(k.gyroSign[0] < 0 ? "−" : "+")
                                                             .arg(k.gyroSign[1] < 0 ? "−" : "+")
                                                             .arg(k.gyroSign[2] < 0 ? "−" : "+"));
  const QString software = r.softwareVersion.empty() ? QObject::tr("version not recorded")
                                                     : "fogbench " + QString::fromStdString(r.softwareVersion);
  const QString input = !r.audit                      ? QObject::tr("raw data not recorded")
                        : r.audit->inputSha256.empty() ? QObject::tr("raw data hash not known")
                                                       : "SHA-256 " + QString::fromStdString(r.audit->inputSha256.substr(0, 12)) + "…";
  return QObject::tr("#%1 %2 %3 · %4 · %5 · %6 · %7")
      .arg(number)
      .arg(when, by, constants, software, input, ui::verdictWord(r.verdict));
}

void constantsAndPlanPage(PageFlow& flow, const Content& c) {
  const auto& info = c.in.info;
  const auto& d = c.in.delays;
  const auto& k = d.constants;
  const auto& rec = c.in.recording;
  const bool imported = c.in.rawBytes.empty();  // another bench's data: no stream, no counter of ours

  flow.heading(QObject::tr("Bench constants"));
  Table consts;
  consts.columns = {{QObject::tr("quantity"), 48, Qt::AlignLeft},
                    {QObject::tr("value"), 34, Qt::AlignRight},
                    {QObject::tr("std. uncertainty"), 30, Qt::AlignRight},
                    {QObject::tr("role"), 62, Qt::AlignLeft}};
  auto uncertainty = [](double sd) { return sd > 0.0 ? fixed(sd, 4) + " ms" : QObject::tr("0 (taken as exact)"); };
  consts.rows = {
      {QObject::tr("table read delay"), fixed(k.tableReadDelayMs, 4) + " ms", uncertainty(k.tableReadDelayStdMs),
       QObject::tr("added to the lag: IMU delay")},
      {QObject::tr("processing-board delay"), fixed(k.boardDelayMs, 4) + " ms", uncertainty(k.boardDelayStdMs),
       QObject::tr("subtracted from the IMU delay: gyro delay")},
      {QObject::tr("gyro pulse equivalent"),
       QObject::tr("%1″/pulse").arg(QString::number(rec.pulseEquivalentDeg * 3600.0, 'g', 4)), "",
       QObject::tr("the stream's statement, else the bench constant: turns pulses into degrees")},
      {QObject::tr("sampling-board counter"),
       imported ? QObject::tr("not stated") : QObject::tr("%1 MHz, %2 bit").arg(rec.counterHz / 1e6).arg(rec.counterBits),
       "",
       imported ? QObject::tr("imported: times in seconds on the other bench's common clock")
                : QObject::tr("common time base of both channels")},
      {QObject::tr("latitude"), QObject::tr("%1°").arg(info.bench.latitudeDeg), "",
       QObject::tr("Earth rate, absorbed by the fitted gyro trend")},
      {QObject::tr("gyro signs"), QString::fromStdString(describeGyroSigns(k.gyroSign)), "",
       QObject::tr("−1: the gyro axis counts against the table's; its increments are negated")},
      {QObject::tr("IMU frame"), coreText(describeImuFrame(info.bench.imuFrame)), "",
       QObject::tr("the IMU's axes at zero table angles; the diagnosis checks it against the data")},
  };
  flow.table(consts);

  flow.heading(QObject::tr("Test plan"));
  if (!info.plan.points.empty()) {
    Table plan;
    plan.columns = {{"#", 10, Qt::AlignLeft},
                    {QObject::tr("axis"), 16, Qt::AlignLeft},
                    {QObject::tr("frequency (Hz)"), 30, Qt::AlignRight},
                    {QObject::tr("amplitude (°)"), 30, Qt::AlignRight},
                    {QObject::tr("duration (s)"), 30, Qt::AlignRight},
                    {QObject::tr("settle (s)"), 26, Qt::AlignRight},
                    {QObject::tr("start phase (°)"), 32, Qt::AlignRight}};
    for (std::size_t i = 0; i < info.plan.points.size(); ++i) {
      const auto& p = info.plan.points[i];
      plan.rows.push_back({QString::number(i + 1), axisUpper(p.axis), QString::number(p.frequencyHz),
                           QString::number(p.amplitudeDeg), QString::number(p.durationS),
                           QString::number(p.settleS), QString::number(p.startPhaseDeg)});
    }
    flow.table(plan);
    flow.paragraph(QObject::tr("Table at rest for %1 s between test points.").arg(info.plan.restBetweenS),
                   PageFlow::font(8.5));
  } else {
    Table plan;
    plan.columns = {{"#", 10, Qt::AlignLeft},
                    {QObject::tr("axis"), 16, Qt::AlignLeft},
                    {QObject::tr("nominal frequency (Hz)"), 44, Qt::AlignRight},
                    {QObject::tr("nominal amplitude (°)"), 44, Qt::AlignRight},
                    {QObject::tr("recorded (s)"), 30, Qt::AlignRight}};
    for (const auto& tp : rec.testPoints) {
      const double span = tp.table.size() > 1 ? tp.table.back().timeS - tp.table.front().timeS : 0.0;
      auto nominal = [](double v) { return v > 0.0 ? QString::number(v) : QObject::tr("not stated"); };
      plan.rows.push_back({QString::number(tp.index + 1), axisUpper(tp.axis), nominal(tp.nominalFrequencyHz),
                           nominal(tp.nominalAmplitudeDeg), fixed(span, 1)});
    }
    flow.paragraph(QObject::tr("The plan was not recorded with the data; the test points as the stream states them:"),
                   PageFlow::font(8.5));
    flow.table(plan);
  }

  flow.heading(QObject::tr("Data integrity"));
  const auto& h = d.health;
  auto n = [](std::uint64_t v) { return QString::number(static_cast<qulonglong>(v)); };
  Table health;
  health.columns = {{"", 52, Qt::AlignLeft}, {"", 30, Qt::AlignRight}, {"", 62, Qt::AlignLeft}, {"", 30, Qt::AlignRight}};
  health.rows = {{QObject::tr("table frames"), n(h.tableFrames), QObject::tr("checksum failures"), n(h.checksumFailures)},
                 {QObject::tr("IMU frames"), n(h.imuFrames), QObject::tr("lost frames"), n(h.lostFrames)},
                 {QObject::tr("status frames"), n(h.statusFrames), QObject::tr("duplicate / out-of-order frames"),
                  n(h.duplicateFrames) + " / " + n(h.outOfOrderFrames)},
                 {QObject::tr("counter wraps"), n(h.counterWraps), QObject::tr("bytes skipped"), n(h.bytesSkipped)}};
  flow.table(health);

  // The audit trail: every stored analysis of the session, who made it with
  // what on which data (the lines as the core words them, never re-judged).
  if (!c.in.analyses.empty()) {
    flow.heading(QObject::tr("Analyses of this session"));
    for (std::size_t i = 0; i < c.in.analyses.size(); ++i)
      flow.paragraph(auditLine(static_cast<int>(i) + 1, c.in.analyses[i]), PageFlow::font(7.5));
    flow.paragraph(QObject::tr("Each line: number, when stored (UTC), who (operator named, or login), tool and "
                               "command, constants, software version, SHA-256 of the raw data analysed (first 12 "
                               "digits), verdict as stored."),
                   PageFlow::font(7.0), kMuted);
  }

  budgetSection(flow, c, imported);

  Table resolution;
  resolution.columns = {{QObject::tr("test point"), 64, Qt::AlignLeft},
                        {QObject::tr("paper's resolution, 0.5 °/h (µs)"), 40, Qt::AlignRight},
                        {QObject::tr("Cramér–Rao bound (µs)"), 36, Qt::AlignRight},
                        {QObject::tr("lag std. error (µs)"), 34, Qt::AlignRight}};
  for (const auto& p : d.points)
    resolution.rows.push_back(
        {QObject::tr("#%1: %2").arg(p.index + 1).arg(shortCondition(p).replace('\n', ", ")),
         fixed(analysis::paperResolutionS(0.5, p.nominalFrequencyHz, p.tableFit.amplitudeDeg) * 1e6, 2),
         fixed(p.crlbMs * 1e3, 3), fixed(p.lagStdMs * 1e3, 3)});
  flow.table(resolution);
  flow.paragraph(QObject::tr("The paper's resolution figure is the gyro's angle error over one period divided by "
                             "the peak rate; the bench's own uncertainty is the joint fit's standard error, checked "
                             "against the Cramér–Rao bound for the noise measured in this session."),
                 PageFlow::font(7.5), kMuted);
}

double traceRms(const ui::Trace& t) {
  if (t.y.empty()) return 0.0;
  double s = 0.0;
  for (double v : t.y) s += v * v;
  return std::sqrt(s / static_cast<double>(t.y.size()));
}

void plotsPage(PageFlow& flow, const TestPointResult& p, const ui::TestPointTraces& tr) {
  flow.newPage();
  flow.heading(QObject::tr("Test point %1: %2 — angles and fits").arg(p.index + 1).arg(condition(p)));
  const double periodS = p.joint.frequencyHz > 0.0 ? 1.0 / p.joint.frequencyHz : 1.0 / p.nominalFrequencyHz;
  const auto& tx = tr.tableNormalised.x;
  const double start = tx.empty() ? 0.0 : tx.front(), end = tx.empty() ? 1.0 : tx.back();
  const double mid = 0.5 * (start + end);
  const double w0 = std::max(start, mid - 1.5 * periodS), w1 = std::min(end, mid + 1.5 * periodS);
  flow.paragraph(QObject::tr("Angles: the middle three periods (%1 s to %2 s on the board's time axis), offset "
                             "removed; the gyro angle is the sum of its increments with the fitted trend (bias + "
                             "Earth rate) removed. Fits: the 4-parameter fits of the table below. Residuals: the "
                             "whole record (%3 s), data minus fit; the table's are its encoder quantisation, the "
                             "gyro's its angle random walk and pulse quantisation.")
                     .arg(fixed(w0, 1), fixed(w1, 1), fixed(p.durationS, 1)),
                 PageFlow::font(8.0), kMuted);
  const double plotH = (flow.remainingMm() - 4 * PageFlow::kPlotGapMm) / 4.0;
  const double tableAmp = std::hypot(tr.tableFit.a, tr.tableFit.b);
  const double gyroAmp = std::hypot(tr.gyroFit.a, tr.gyroFit.b);
  // The recording's own sample intervals (another bench's may be 11 and 20 ms).
  auto stepMs = [&](std::size_t samples) {
    return QString::number(samples > 1 ? 1e3 * p.durationS / static_cast<double>(samples - 1) : 0.0, 'g', 3);
  };
  const QString tableStepMs = stepMs(p.tableSamples), gyroStepMs = stepMs(p.imuSamples);

  flow.plot(plotH, [&](double wMm, double) {
    detail::PlotSpec s;
    s.title = QObject::tr("Table angle (offset removed) and fit");
    s.xTitle = QObject::tr("time (s)");
    s.yTitle = QObject::tr("angle (°)");
    s.x0 = w0;
    s.x1 = w1;
    s.yRange = {-1.15 * tableAmp, 1.15 * tableAmp};
    s.widthMm = wMm;
    s.curves = {{QObject::tr("table angle (encoder, %1 ms)").arg(tableStepMs), QPen(kTableData, 3.0),
                 &tr.tableNormalised, tableAmp, {}},
                {QObject::tr("fit: A = %1°, T = %2 ms").arg(fixed(p.tableFit.amplitudeDeg, 4), fixed(p.tableFit.periodMs, 4)),
                 QPen(kTableFit, 1.0, Qt::DashLine), nullptr, 1.0,
                 [&tr, tableAmp](double t) { return tr.tableFitNormalised(t) * tableAmp; }}};
    return detail::makePlot(s);
  });
  flow.plot(plotH, [&](double wMm, double) {
    detail::PlotSpec s;
    s.title = QObject::tr("Gyro angle (offset and trend removed) and fit");
    s.xTitle = QObject::tr("time (s)");
    s.yTitle = QObject::tr("angle (°)");
    s.x0 = w0;
    s.x1 = w1;
    s.yRange = {-1.15 * gyroAmp, 1.15 * gyroAmp};
    s.widthMm = wMm;
    s.curves = {{QObject::tr("gyro angle (summed increments, %1 ms)").arg(gyroStepMs), QPen(kGyroData, 3.0),
                 &tr.gyroNormalised, gyroAmp, {}},
                {QObject::tr("fit: A = %1°, T = %2 ms").arg(fixed(p.gyroFit.amplitudeDeg, 4), fixed(p.gyroFit.periodMs, 4)),
                 QPen(kGyroFit, 1.0, Qt::DashLine), nullptr, 1.0,
                 [&tr, gyroAmp](double t) { return tr.gyroFitNormalised(t) * gyroAmp; }}};
    return detail::makePlot(s);
  });
  flow.plot(plotH, [&](double wMm, double) {
    detail::PlotSpec s;
    s.title = QObject::tr("Table residuals");
    s.xTitle = QObject::tr("time (s)");
    s.yTitle = QObject::tr("table − fit (arcsec)");
    s.x0 = start;
    s.x1 = end;
    s.widthMm = wMm;
    s.curves = {{QObject::tr("table angle − fit, RMS %1″").arg(fixed(traceRms(tr.tableResidualArcsec), 3)),
                 QPen(kTableFit, 0.8), &tr.tableResidualArcsec, 1.0, {}}};
    return detail::makePlot(s);
  });
  flow.plot(plotH, [&](double wMm, double) {
    detail::PlotSpec s;
    s.title = QObject::tr("Gyro residuals (cumulative angle)");
    s.xTitle = QObject::tr("time (s)");
    s.yTitle = QObject::tr("gyro − fit (arcsec)");
    s.x0 = start;
    s.x1 = end;
    s.widthMm = wMm;
    s.curves = {{QObject::tr("gyro angle − fit, RMS %1″").arg(fixed(traceRms(tr.gyroResidualArcsec), 3)),
                 QPen(kGyroFit, 0.8), &tr.gyroResidualArcsec, 1.0, {}}};
    return detail::makePlot(s);
  });
}

QStringList fitRow(const QString& name, const SineFit& f, bool frequencyFree) {
  return {name,
          fixed(f.periodMs, 4),
          frequencyFree ? plain2(f.periodStdMs * 1e3) : QObject::tr("nominal"),
          fixed(f.phaseMs, 4),
          plain2(f.phaseStdMs * 1e3),
          fixed(f.amplitudeDeg, 5),
          plain2(f.amplitudeStdDeg * 3600.0),
          fixed(f.chiSquarePerDof, 2)};
}

void resultsPage(PageFlow& flow, const Content& c, const TestPointResult& p, const PointVerdict& v) {
  const auto& k = c.in.delays.constants;
  flow.newPage();
  flow.heading(QObject::tr("Test point %1: %2 — fits and delay").arg(p.index + 1).arg(condition(p)));

  Table fits;
  fits.columns = {{QObject::tr("fit"), 36, Qt::AlignLeft},
                  {QObject::tr("period T (ms)"), 22, Qt::AlignRight},
                  {QObject::tr("σ(T) (µs)"), 18, Qt::AlignRight},
                  {QObject::tr("phase t₀ (ms)"), 23, Qt::AlignRight},
                  {QObject::tr("σ(t₀) (µs)"), 18, Qt::AlignRight},
                  {QObject::tr("amplitude A (°)"), 22, Qt::AlignRight},
                  {QObject::tr("σ(A) (″)"), 17, Qt::AlignRight},
                  {QObject::tr("χ²/dof"), 18, Qt::AlignRight}};
  fits.rows = {fitRow(QObject::tr("table, 3-parameter"), p.tableNominal, false),
               fitRow(QObject::tr("gyro, 3-parameter"), p.gyroNominal, false),
               fitRow(QObject::tr("table, 4-parameter"), p.tableFit, true),
               fitRow(QObject::tr("gyro, 4-parameter"), p.gyroFit, true)};
  const double f = p.joint.frequencyHz;
  const int dec = decimalsFor(p.lagStdMs);
  fits.rows.push_back({QObject::tr("joint: lag as t₀"), f > 0.0 ? fixed(1e3 / f, 4) : "—",
                       plain2(f > 0.0 ? 1e6 * p.joint.frequencyStdHz / (f * f) : 0.0), fixed(p.lagMs, dec),
                       plain2(p.lagStdMs * 1e3), fixed(std::hypot(p.joint.a, p.joint.b), 5), "—",
                       fixed(p.joint.chiSquarePerDof, 2)});
  fits.boldRows = {false, false, false, false, true};
  flow.table(fits);
  flow.paragraph(QObject::tr("angle = A sin(2π (t − t₀)/T) + offset (gyro: + trend·t), t₀ wrapped into (−T/2, T/2]; "
                             "σ: standard uncertainties (1σ). 3-parameter fits at the nominal frequency (a χ²/dof far "
                             "above 1 says the table's frequency is off nominal), 4-parameter fits with the frequency "
                             "free, and the joint fit: one frequency for both channels and the lag (gyro t₀ − table "
                             "t₀) as a parameter; its gyro/table amplitude ratio is %1 ± %2.")
                     .arg(fixed(p.magnitudeRatio, 6), plain2(p.gainStd)),
                 PageFlow::font(7.5), kMuted);

  Table delay;
  delay.columns = {{QObject::tr("quantity"), 62, Qt::AlignLeft},
                   {QObject::tr("value (ms)"), 24, Qt::AlignRight},
                   {QObject::tr("1σ (ms)"), 22, Qt::AlignRight},
                   {QObject::tr("basis"), 66, Qt::AlignLeft}};
  delay.rows = {
      {QObject::tr("measured lag (gyro behind table)"), fixed(p.lagMs, dec), fixed(p.lagStdMs, dec),
       QObject::tr("joint fit; CRLB %1 ms, σ/CRLB %2").arg(fixed(p.crlbMs, dec), fixed(p.stdOverCrlb, 2)) +
           (analysis::sigmaBelowBound(p) ? QObject::tr(" — σ below the bound: understated (check uncertainty_below_bound)")
                                         : QString())},
      {QObject::tr("+ table read delay"), fixed(k.tableReadDelayMs, dec), fixed(k.tableReadDelayStdMs, dec),
       QObject::tr("bench constant")},
      {QObject::tr("= IMU delay"), fixed(p.imuDelayMs, dec), fixed(p.imuDelayStdMs, dec),
       QObject::tr("limit %1 ms: %2").arg(limitText(c.in.imuDelayLimitMs), v.word)},
      {QObject::tr("− processing-board delay"), fixed(k.boardDelayMs, dec), fixed(k.boardDelayStdMs, dec),
       QObject::tr("bench constant")},
      {QObject::tr("= gyro's own delay"), fixed(p.gyroDelayMs, dec), fixed(p.gyroDelayStdMs, dec), ""},
      {QObject::tr("per-period lag, mean and scatter"), fixed(p.periodMeanLagMs, dec), fixed(p.periodScatterMs, dec),
       QObject::tr("%1 whole periods, 3-parameter fits").arg(p.periodTrack.size())},
  };
  delay.boldRows = {true, false, true, false, true, false};
  flow.heading(QObject::tr("Delay"));
  flow.table(delay);
  flow.paragraph(v.line, PageFlow::font(9.0, true), v.pass ? kPassColour : kFailColour);
  flow.paragraph(v.vouched && std::isfinite(v.falseAcceptProbability)
                     ? QObject::tr("Guard band kσ = %1 ms (k = %2); probability that the true IMU delay is at or "
                                   "above the limit: %3.")
                           .arg(fixed(v.guardBandMs, dec),
                                QString::fromStdString(analysis::coverageFactorText(c.verdict.coverageK)),
                                pointRiskText(v))
                     : QObject::tr("No false-accept probability: the delay is refused (%1).").arg(v.word),
                 PageFlow::font(8.0), kMuted);

  if (!p.periodTrack.empty()) {
    flow.plot(58.0, [&](double wMm, double) {
      detail::PlotSpec s;
      s.title = QObject::tr("Lag per swing period");
      s.xTitle = QObject::tr("time (s)");
      s.yTitle = QObject::tr("lag (ms)");
      const double half = 0.5 * (f > 0.0 ? 1.0 / f : 1.0);
      s.x0 = p.periodTrack.front().timeS - half;
      s.x1 = p.periodTrack.back().timeS + half;
      s.widthMm = wMm;
      auto track = std::make_shared<ui::Trace>();
      for (const auto& d : p.periodTrack) {
        track->x.push_back(d.timeS);
        track->y.push_back(d.lagMs);
      }
      s.curves = {{QObject::tr("one period"), QPen(kTableFit), track.get(), 1.0, {}, true}};
      s.horizontalLine = p.lagMs;
      s.horizontalLineTitle = QObject::tr("joint fit, %1 ms").arg(fixed(p.lagMs, dec));
      auto plot = detail::makePlot(s);  // copies the points: the track may go
      return plot;
    });
  }

  flow.heading(QObject::tr("Noise and fit quality"));
  std::vector<std::pair<QString, QString>> rows = {
      {QObject::tr("encoder noise"), QObject::tr("%1″ (1σ)").arg(fixed(p.noise.tableNoiseDeg * 3600.0, 3))},
      {QObject::tr("gyro pulse quantisation"), QObject::tr("%1″ (1σ)").arg(fixed(p.noise.gyroQuantisationDeg * 3600.0, 3))},
      {QObject::tr("gyro angle random walk"), QObject::tr("%1 °/√h").arg(fixed(p.noise.gyroArwDegPerSqrtH, 4))},
      {QObject::tr("gyro trend"), QObject::tr("%1 °/h (bias + Earth rate)").arg(fixed(p.joint.trendDegPerS * 3600.0, 3))},
      {QObject::tr("samples"), QObject::tr("%1 table, %2 IMU, %3 IMU frames lost")
                                   .arg(static_cast<qulonglong>(p.tableSamples))
                                   .arg(static_cast<qulonglong>(p.imuSamples))
                                   .arg(static_cast<qulonglong>(p.lostImuFrames))},
  };
  flow.keyValues(rows, 48.0);
  if (!p.warnings.empty()) {
    flow.heading(QObject::tr("Warnings"));
    for (const auto& w : p.warnings) flow.paragraph("• " + coreText(w), PageFlow::font(8.5), kFailColour);
  }
}

// A static segment: the gyro's Allan deviation, its noise terms and bias.
void noisePage(PageFlow& flow, const noise::GyroNoiseReport& r) {
  flow.newPage();
  flow.heading(QObject::tr("Test point %1: %2 gyro at rest for %3 s — noise")
                   .arg(r.testPointIndex + 1)
                   .arg(axisUpper(r.gyroAxis))
                   .arg(fixed(r.durationS, 0)));
  flow.plot(110.0, [&](double, double) {
    auto plot = detail::makeFramePlot(QObject::tr("Overlapping Allan deviation of the gyro"));
    ui::drawAllanCurves(plot.get(), r,
                        {QObject::tr("averaging time τ (s)"), QObject::tr("Allan deviation (°/h)"),
                         QObject::tr("confidence interval (%1 %)"), QObject::tr("measured"),
                         QObject::tr("noise model (sum)"),
                         {QObject::tr("quantisation"), QObject::tr("angle random walk"), QObject::tr("bias instability"),
                          QObject::tr("rate random walk"), QObject::tr("rate ramp"), QObject::tr("Gauss–Markov bias")}});
    detail::restyleAxisTitles(plot.get());
    return plot;
  });
  Table terms;
  terms.columns = {{QObject::tr("noise term"), 50, Qt::AlignLeft},
                   {QObject::tr("value"), 28, Qt::AlignRight},
                   {QObject::tr("± 1σ"), 24, Qt::AlignRight},
                   {QObject::tr("unit"), 34, Qt::AlignLeft},
                   {QObject::tr("from τ (s)"), 38, Qt::AlignLeft}};
  for (const auto& t : r.model.terms) {
    const auto u = noise::termInGyroUnits(t);
    terms.rows.push_back({coreText(noise::noiseTermName(t.kind)), QString::number(u.value, 'g', 4),
                          QString::number(u.stdError, 'g', 2), ui::displayUnits(QString::fromUtf8(u.unit)),
                          QString("%1 – %2").arg(QString::number(t.tauLowS, 'g', 3), QString::number(t.tauHighS, 'g', 3))});
  }
  flow.heading(QObject::tr("Noise terms (IEEE Std 952)"));
  flow.table(terms);
  flow.keyValues({{QObject::tr("bias"), QObject::tr("%1 ± %2 °/h").arg(fixed(r.biasDegPerH, 4), fixed(r.biasStdDegPerH, 4))},
                  {QObject::tr("Earth rate on this gyro"), QObject::tr("%1 °/h").arg(fixed(r.earthRateDegPerH, 4))},
                  {QObject::tr("Earth-corrected bias"), QObject::tr("%1 °/h").arg(fixed(r.earthCorrectedBiasDegPerH, 4))},
                  {QObject::tr("samples"), QObject::tr("%1 every %2 ms, %3 frames lost")
                                               .arg(static_cast<qulonglong>(r.samples))
                                               .arg(fixed(r.intervalS * 1e3, 3))
                                               .arg(static_cast<qulonglong>(r.lostFrames))},
                  {QObject::tr("model fit"), QObject::tr("χ²/dof %1").arg(fixed(r.model.dof > 0 ? r.model.chiSquare / r.model.dof : 0.0, 2))}},
                 48.0);
  for (const auto& w : r.warnings) flow.paragraph("• " + coreText(w), PageFlow::font(8.5), kFailColour);
}

// An axis's frequency response (docs/method.md "Frequency response"): the
// Bode plot, the points and every fitted model, as the GUI's Bode view and
// `fogbench-cli response` give them.
void responsePage(PageFlow& flow, const analysis::ResponseAnalysis& r) {
  flow.newPage();
  flow.heading(QObject::tr("Frequency response, %1 axis: gyro angle / table angle at %2 frequencies")
                   .arg(axisUpper(r.axis))
                   .arg(r.points.size()));
  const analysis::ResponseModelFit* chosen =
      r.chosen >= 0 && r.chosen < static_cast<int>(r.models.size()) ? &r.models[static_cast<std::size_t>(r.chosen)] : nullptr;
  const std::vector<ui::BodeSeries> series = {
      {QObject::tr("measured ±1σ"), kTableFit, r.points, chosen, QObject::tr("model (chosen)")}};
  for (const auto& [part, title, yTitle] :
       {std::tuple{ui::BodePart::kMagnitudeDb, QObject::tr("Magnitude"), QObject::tr("|H| (dB)")},
        std::tuple{ui::BodePart::kPhaseDeg, QObject::tr("Phase (negative: the gyro lags)"), QObject::tr("phase (°)")}}) {
    flow.plot(62.0, [&, part = part, title = title, yTitle = yTitle](double, double) {
      auto plot = detail::makeFramePlot(title);
      ui::drawBodeCurves(plot.get(), part, series, {QObject::tr("frequency (Hz)"), yTitle});
      detail::restyleAxisTitles(plot.get());
      return plot;
    });
  }

  Table points;
  points.columns = {{QObject::tr("point"), 12, Qt::AlignRight},    {QObject::tr("f (Hz)"), 18, Qt::AlignRight},
                    {QObject::tr("|H|"), 22, Qt::AlignRight},      {QObject::tr("σ"), 15, Qt::AlignRight},
                    {QObject::tr("|H| (dB)"), 19, Qt::AlignRight}, {QObject::tr("σ (dB)"), 15, Qt::AlignRight},
                    {QObject::tr("phase (°)"), 19, Qt::AlignRight}, {QObject::tr("σ (°)"), 15, Qt::AlignRight},
                    {QObject::tr("lag (ms)"), 18, Qt::AlignRight}, {QObject::tr("σ (ms)"), 15, Qt::AlignRight}};
  points.fontPt = 7.5;
  auto sci = [](double v) { return QString::number(v, 'g', 2); };
  for (const auto& p : r.points)
    points.rows.push_back({QString::number(p.index + 1), fixed(p.frequencyHz, 4), fixed(p.magnitude, 7), sci(p.magnitudeStd),
                           fixed(p.magnitudeDb, 6), sci(p.magnitudeDbStd), fixed(p.phaseDeg, 4), sci(p.phaseStdDeg),
                           fixed(p.lagMs, 5), sci(p.lagStdMs)});
  flow.table(points);
  flow.paragraph(QObject::tr("Complex gain of each test point that passed its checks, from its joint fit: magnitude "
                             "gyro/table amplitude, phase −2π f · lag; standard uncertainties (1σ)."),
                 PageFlow::font(7.5), kMuted);

  // The certificate's figure per point: the phase against the table's motion
  // with its expanded uncertainty (certifiedPhase), as `response` gives it.
  Table certified;
  certified.columns = {{QObject::tr("point"), 12, Qt::AlignRight},
                       {QObject::tr("f (Hz)"), 18, Qt::AlignRight},
                       {QObject::tr("phase vs motion (°)"), 30, Qt::AlignRight},
                       {QObject::tr("u, fit (°)"), 20, Qt::AlignRight},
                       {QObject::tr("u, read delay (°)"), 24, Qt::AlignRight},
                       {QObject::tr("U (k = 2), °"), 22, Qt::AlignRight},
                       {QObject::tr("U (k = 2), ms"), 22, Qt::AlignRight}};
  certified.fontPt = 7.5;
  for (const auto& p : r.points) {
    const analysis::CertifiedPhase c = analysis::certifiedPhase(p, r);
    certified.rows.push_back({QString::number(p.index + 1), fixed(p.frequencyHz, 4), fixed(c.phaseDeg, 4),
                              sci(c.fitStdDeg), sci(c.readDelayStdDeg), sci(c.expandedDeg), sci(c.expandedMs)});
  }
  flow.table(certified);
  flow.paragraph(QObject::tr("The phase against the table's motion: the phase above less 2π f · d (d = %1 ms, the table "
                             "read delay); its expanded uncertainty U = k·√(u_f² + u_d²) with k = 2, u_f the fit's and u_d = "
                             "2π f · %2 ms (the read delay's standard uncertainty).")
                     .arg(fixed(r.tableReadDelayMs, 4), sci(r.tableReadDelayStdMs)),
                 PageFlow::font(7.5), kMuted);

  flow.heading(QObject::tr("Models fitted to all points (weighted least squares on magnitude and phase)"));
  Table models;
  models.columns = {{QObject::tr("model"), 40, Qt::AlignLeft},
                    {QObject::tr("χ²/dof"), 14, Qt::AlignRight},
                    {QObject::tr("p (fit)"), 14, Qt::AlignRight},
                    {QObject::tr("AIC"), 17, Qt::AlignRight},
                    {QObject::tr("BIC"), 17, Qt::AlignRight},
                    {QObject::tr("parameters (± 1σ)"), 72, Qt::AlignLeft}};
  models.fontPt = 7.5;
  for (std::size_t i = 0; i < r.models.size(); ++i) {
    const auto& m = r.models[i];
    models.rows.push_back({ui::responseModelTitle(m.kind), m.dof > 0 ? fixed(m.chiSquare / m.dof, 2) : "—",
                           QString::number(m.pValue, 'g', 2),
                           fixed(m.aic, 1), fixed(m.bic, 1), ui::responseParametersText(m)});
    models.boldRows.push_back(static_cast<int>(i) == r.chosen);
  }
  flow.table(models);
  for (const auto& skipped : r.skipped)
    flow.paragraph(QObject::tr("Model left out: %1").arg(coreText(skipped)), PageFlow::font(7.5), kMuted);
  flow.paragraph(QObject::tr("p (fit): the probability of a χ² this large were the model true. A model is chosen only "
                             "when its fit is adequate (p ≥ %1) and its parameters are physical (docs/method.md).")
                     .arg(QString::number(analysis::kModelAdequacyP, 'g', 2)),
                 PageFlow::font(7.5), kMuted);
  for (const auto& m : r.models)
    for (const auto& why : m.inadmissible)
      flow.paragraph(QObject::tr("%1 is not admissible: %2").arg(ui::responseModelTitle(m.kind), coreText(why)),
                     PageFlow::font(7.5), kMuted);
  if (!chosen && !r.models.empty())
    flow.paragraph(QObject::tr("No model fits: the measured points alone are the response. %1")
                       .arg(coreText(r.noModelReason)),
                   PageFlow::font(8.5), kFailColour);
  if (chosen) {
    std::vector<std::pair<QString, QString>> rows = {
        {QObject::tr("chosen (lowest AIC; a filter at 3σ)"), ui::responseModelTitle(chosen->kind)},
        {QObject::tr("low-frequency delay"),
         ui::valueWithStdText(chosen->lowFrequencyDelayMs.value, chosen->lowFrequencyDelayMs.stdDev, QObject::tr("ms"))},
        {QObject::tr("group delay at %1 Hz").arg(QString::number(r.groupDelayAtHz, 'g', 4)),
         ui::valueWithStdText(chosen->groupDelayMs.value, chosen->groupDelayMs.stdDev, QObject::tr("ms"))},
        {QObject::tr("−3 dB bandwidth"),
         chosen->bandwidthHz ? ui::valueWithStdText(chosen->bandwidthHz->value, chosen->bandwidthHz->stdDev, QObject::tr("Hz"))
                             : QObject::tr("none: a pure delay keeps its magnitude")}};
    flow.keyValues(rows, 48.0);
    for (const auto& n : chosen->notes) flow.paragraph("• " + coreText(n), PageFlow::font(8.0), kMuted);
  }
}

void layOut(PageFlow& flow, const Content& c) {
  flow.newPage();
  firstPage(flow, c);
  flow.newPage();
  constantsAndPlanPage(flow, c);
  for (const auto& r : c.responses) responsePage(flow, r);
  const auto& points = c.in.delays.points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    plotsPage(flow, points[i], c.traces[i]);
    resultsPage(flow, c, points[i], c.verdict.points[i]);
  }
  for (const auto& r : c.noise) noisePage(flow, r);
  flow.finish();
}

Result<Content> prepare(const ReportInput& in) {
  if (auto s = checkReportInput(in); !s.isOk()) return s;
  if (!qobject_cast<QApplication*>(QCoreApplication::instance()))
    return Status(StatusCode::kInternal, "the report's plots need a QApplication");
  Content c{in, calibrationVerdict(in), rawDataSha256(in.rawBytes), {},
            QDateTime::currentDateTimeUtc().toString(Qt::ISODate), {}, {}};
  for (const auto& p : in.delays.points) {
    const auto& tps = in.recording.testPoints;
    const auto data = std::find_if(tps.begin(), tps.end(), [&](const TestPointData& d) { return d.index == p.index; });
    auto traces = ui::makeTestPointTraces(*data, p);
    if (!traces)
      return Status(traces.status().code(),
                    "test point " + std::to_string(p.index + 1) + " cannot be plotted: " + traces.status().message());
    c.traces.push_back(std::move(*traces));
  }
  // A response plan's frequency response (RunOutcome::responses is the same
  // analysis of the same report). Two frequencies (the paper's plan) are the
  // delay table's business: the page is for three or more.
  for (auto& r : analysis::analyzeResponses(in.delays))
    if (r.points.size() >= 3) c.responses.push_back(std::move(r));
  // The static segments' noise, when the plan had any.
  if (std::any_of(in.recording.testPoints.begin(), in.recording.testPoints.end(),
                  [](const TestPointData& d) { return d.kind == TestPointKind::kStatic; })) {
    noise::GyroNoiseOptions options;
    options.earth.latitudeDeg = in.info.bench.latitudeDeg;
    model::applyImuFrame(in.info.bench.imuFrame, options.earth);
    auto reports = noise::analyzeGyroNoise(in.recording, options);
    if (!reports) return Status(reports.status().code(), "the static segments' noise: " + reports.status().message());
    c.noise = std::move(*reports);
  }
  return c;
}

// Lays the pages out once to count them, then draws them.
template <typename Target>
void render(Target& target, const Content& c, QStringList* drawn) {
  auto deco = [&c](PageFlow& f, int page, int count) { decorate(f, c, page, count); };
  MeasureTarget measure(target);
  PageFlow counting(measure, 0, deco, nullptr);
  layOut(counting, c);
  PageFlow drawing(target, counting.page(), deco, drawn);
  layOut(drawing, c);
}

}  // namespace

ReportInput makeReportInput(SessionInfo info, Recording recording, analysis::DelayReport delays,
                            std::vector<std::uint8_t> rawBytes, const session::StoredResultRecord* stored,
                            double limitMs, const std::string& incompleteReason, QString resultShown,
                            double coverageK) {
  ReportInput in;
  in.info = std::move(info);
  in.recording = std::move(recording);
  in.delays = std::move(delays);
  in.rawBytes = std::move(rawBytes);
  in.resultShown = std::move(resultShown);
  if (stored) {
    // A record: printed with the limit it was judged with, as stored.
    in.stored = *stored;
    in.imuDelayLimitMs = stored->imuDelayLimitMs;
    in.coverageK = stored->coverageK;
  } else {
    in.imuDelayLimitMs = limitMs;
    in.coverageK = coverageK;
    in.incompleteReason = incompleteReason;
  }
  return in;
}

QString rawDataSha256(const std::vector<std::uint8_t>& bytes) {
  if (bytes.empty()) return {};
  QCryptographicHash hash(QCryptographicHash::Sha256);
  constexpr std::size_t kChunk = std::size_t(1) << 26;  // keeps the length within int on Qt 5
  for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
    const auto n = static_cast<int>(std::min(kChunk, bytes.size() - at));
    const char* data = reinterpret_cast<const char*>(bytes.data() + at);
#if QT_VERSION >= QT_VERSION_CHECK(6, 3, 0)
    hash.addData(QByteArrayView(data, n));
#else
    hash.addData(data, n);
#endif
  }
  return QString::fromLatin1(hash.result().toHex());
}

namespace {

// The verdict of the page: core's shown verdict (session::judgeShown) in the
// report's words. Nothing is judged here.
Verdict formatVerdict(const session::ShownVerdict& shown, const DelayReport& delays) {
  using K = session::ShownVerdictKind;
  Verdict v;
  v.pass = shown.verdict == K::kPass;
  v.word = ui::verdictWord(shown.verdict);
  v.limitMs = shown.limitMs;
  v.coverageK = shown.coverageK;
  v.ruleProvenance = QString::fromStdString(shown.ruleProvenance);
  int failed = 0, invalid = 0;
  for (const auto& p : shown.points) {
    PointVerdict pv;
    pv.index = p.index;
    pv.pass = p.verdict == K::kPass;
    pv.vouched = p.vouched();
    pv.word = ui::verdictWord(p.verdict);
    pv.falseAcceptProbability = p.falseAcceptProbability;
    pv.guardBandMs = p.guardBandMs;
    QStringList why;
    for (const auto& reason : p.reasons) why << coreText(reason);
    pv.line = ui::verdictWord(p.dataVerdict) + ": " + why.join("; ");
    if (p.verdict == K::kIncomplete)
      pv.line = QObject::tr("INCOMPLETE (the run stopped early); its data give %1").arg(pv.line);
    failed += p.dataVerdict == K::kFail;
    invalid += p.dataVerdict == K::kInvalid;
    v.points.push_back(pv);
  }
  const auto total = static_cast<int>(shown.points.size());
  const auto missing = static_cast<int>(delays.failedPoints.size());
  const QString limit = limitText(shown.limitMs);
  switch (shown.verdict) {
    case K::kPass:
      v.headline = QObject::tr("PASS: every test point passed its validity checks and its IMU delay + %1σ is below "
                               "the %2 ms limit.")
                       .arg(QString::fromStdString(analysis::coverageFactorText(shown.coverageK)), limit);
      break;
    case K::kFail:
      v.headline = QObject::tr("FAIL against the %1 ms limit: %2 of %3 test points exceed the limit.")
                       .arg(limit)
                       .arg(failed)
                       .arg(total);
      break;
    case K::kInvalid: {
      QStringList why;
      if (invalid > 0) why << QObject::tr("%1 of %2 test points failed a validity check").arg(invalid).arg(total);
      if (missing > 0) why << QObject::tr("%1 test point(s) gave no delay").arg(missing);
      if (total == 0) why << QObject::tr("no test point gave a delay");
      if (why.isEmpty())
        for (const auto& reason : shown.reasons) why << coreText(reason);
      v.headline = QObject::tr("INVALID: the result cannot be vouched for: %1.").arg(why.join("; "));
      break;
    }
    case K::kIncomplete:
      v.headline = QObject::tr("INCOMPLETE: the run stopped before its plan ended (%1); no calibration verdict. The "
                               "data recorded give %2.")
                       .arg(coreText(shown.incompleteReason), ui::verdictWord(shown.dataVerdict));
      break;
    case K::kNone:
      v.headline = QObject::tr("NO VERDICT: the stored result states none; re-analyse the session to store one.");
      break;
  }
  return v;
}

}  // namespace

Verdict calibrationVerdict(const DelayReport& delays, double limitMs) {
  return formatVerdict(session::judgeShown(nullptr, &delays, true, {}, limitMs), delays);
}

Verdict calibrationVerdict(const ReportInput& in) {
  Verdict v = formatVerdict(session::judgeShown(in.stored ? &*in.stored : nullptr, &in.delays,
                                                in.incompleteReason.empty(), in.incompleteReason, in.imuDelayLimitMs,
                                                in.coverageK),
                            in.delays);
  if (!in.stored) return v;
  const auto differences = session::differencesFromRecord(*in.stored, in.delays);
  if (!differences.empty()) {
    QStringList d;
    for (const auto& s : differences) d << coreText(s);
    v.headline += " " + QObject::tr("This version's analysis of the same data with the stored settings differs from "
                                    "the stored result (%1); the verdict is the stored one.")
                            .arg(d.join("; "));
  }
  return v;
}

Status checkReportInput(const ReportInput& in) {
  if (!std::isfinite(in.imuDelayLimitMs) || !(in.imuDelayLimitMs > 0.0))
    return invalidArgument("the IMU delay limit must be a number > 0 ms");
  if (const std::string why = analysis::coverageFactorProblem(in.coverageK); !why.empty()) return invalidArgument(why);
  for (const auto& p : in.delays.points) {
    const auto& tps = in.recording.testPoints;
    if (std::none_of(tps.begin(), tps.end(), [&](const TestPointData& d) { return d.index == p.index; }))
      return invalidArgument("the recording has no data for analysed test point " + std::to_string(p.index + 1));
  }
  return Status::ok();
}

Status writeCalibrationPdf(const ReportInput& in, const QString& pdfPath) {
  FOG_ASSIGN_OR_RETURN(auto content, prepare(in));
  PdfTarget target(pdfPath);
  target.setTitle(QObject::tr("IMU delay calibration report: %1 %2")
                      .arg(QString::fromStdString(in.info.imuModel), QString::fromStdString(in.info.imuSerial)));
  if (!target.open()) return ioError("cannot write the PDF '" + pdfPath.toStdString() + "'");
  render(target, content, nullptr);
  target.close();
  if (!QFileInfo(pdfPath).isFile() || QFileInfo(pdfPath).size() == 0)
    return ioError("the PDF '" + pdfPath.toStdString() + "' was not written");
  return Status::ok();
}

Result<std::vector<QImage>> renderCalibrationPages(const ReportInput& in, int dpi, QStringList* drawnText) {
  if (dpi < 30 || dpi > 1200) return invalidArgument("page images need 30 to 1200 dpi");
  FOG_ASSIGN_OR_RETURN(auto content, prepare(in));
  ImageTarget target(dpi);
  render(target, content, drawnText);
  return target.take();
}

}  // namespace fog::report
