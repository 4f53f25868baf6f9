// The core's messages of every kind, made by the core itself (a diagnosis,
// an analysis and its verdict, sources and a stopped run, unreadable session
// files, noise terms), shown through coreText() in Chinese: no English word
// may be left but units, acronyms and identifiers.

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <sys/stat.h>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/acquisition/acquisition.h"
#include "core/acquisition/replay_source.h"
#include "core/acquisition/simulator_source.h"
#include "core/session/stored_result.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/analysis/verdict.h"
#include "core/diagnosis/blind_check.h"
#include "core/diagnosis/diagnosis.h"
#include "core/diagnosis/effects.h"
#include "core/model/simulator.h"
#include "core/analysis/frequency_response.h"
#include "core/analysis/gain_check.h"
#include "core/noise/noise_terms.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"
#include "ui/core_text.h"
#include "ui/language/language.h"

namespace {

using namespace fog;

// Words a Chinese operator reads as they are: units, acronyms, names.
const QStringList kKept = {"IMU", "ARW", "chi", "ppm", "rms", "dof", "Hz", "ms", "fogbench", "SQLite", "Allan",
                           "IEEE", "printf", "dd", "COPY", "fbs", "conv", "notrunc", "of", "format", "urad",
                           "udeg", "us", "sigma", "CRLB", "AIC", "BIC", "sin", "cos", "ioctl", "KiB", "MiB", "FIFO",
                           "ISO", "IEC", "ILAC"};  // the decision rule's standards

// English left in a translated text: runs of three or more Latin letters that
// are not kept words, identifiers (with _ . or -), a command with its option
// and its value ("import --frame-period-ms", "run --preset response"), the given path or a device's path (/dev/...).
QStringList englishIn(QString text, const QString& path = {}) {
  if (!path.isEmpty()) text.replace(path, "");
  static const QRegularExpression device(R"(/dev/[A-Za-z0-9/]+)");
  text.replace(device, " ");
  static const QRegularExpression identifier(R"([A-Za-z0-9]*[_.][A-Za-z0-9_.]*|(?:[a-z]+ )?--[a-z-]+(?: [a-z][a-z0-9-]*)?)");
  text.replace(identifier, " ");
  static const QRegularExpression word(R"([A-Za-z]{3,})");
  QStringList left;
  for (auto it = word.globalMatch(text); it.hasNext();) {
    const QString w = it.next().captured(0);
    if (!kKept.contains(w)) left << w;
  }
  return left;
}

class CoreTextTest : public QObject {
  Q_OBJECT

  int checked_ = 0;
  QStringList failures_;  // of the test function running; every one is reported

  void expectChinese(const std::string& english, const QString& path = {}) {
    const QString shown = ui::coreText(english);
    const QStringList left = englishIn(shown, path);
    ++checked_;
    if (!left.isEmpty() && !failures_.contains(shown))
      failures_ << QString("untranslated '%1' in:\n  %2\n  (from: %3)").arg(left.join("', '"), shown, QString::fromStdString(english));
  }

  void expectEveryLineChinese(const std::string& text) {
    for (const QString& line : QString::fromStdString(text).split('\n')) expectChinese(line.toStdString());
  }

  static Recording simulated(std::vector<std::unique_ptr<model::Effect>> effects, std::uint64_t seed,
                             const TestPlan& plan = diagnosis::blindCheckPlan()) {
    model::SimConfig c;
    c.seed = seed;
    c.fog.setOwnDelayS(0.31e-3);
    auto run = model::simulate(c, plan, std::move(effects));
    if (!run) qFatal("simulation failed: %s", run.status().toString().c_str());
    auto rec = protocol::decodeRecording(run->bytes);
    if (!rec) qFatal("decoding failed: %s", rec.status().toString().c_str());
    return *rec;
  }

  void expectDiagnosisChinese(const Recording& rec, const TestPlan& plan = diagnosis::blindCheckPlan()) {
    SessionInfo info;
    info.plan = plan;
    auto d = diagnosis::diagnose(rec, &info, {}, {});
    QVERIFY2(d.isOk(), d.status().toString().c_str());
    expectEveryLineChinese(diagnosis::formatDiagnosisText(*d));
    expectChinese(d->verdict);
    expectChinese(d->verdictReason);
    for (const auto& e : d->effects) expectChinese(e.name);
    for (const auto& n : d->notes) expectChinese(n);
    for (const auto& g : d->gapMap) {
      expectChinese(diagnosis::channelName(g.key.channel));
      expectChinese(diagnosis::quantityName(g.key));
      expectChinese(diagnosis::quantityTitle(g.key));  // what the text and the gap map show
    }
    for (const auto& e : d->effects) expectChinese(diagnosis::effectTitle(e.name));
    expectChinese(diagnosis::effectTitle(d->verdict));
  }

 private slots:
  void initTestCase() { QCOMPARE(ui::installTranslations(*qApp, "zh_CN"), QString("zh_CN")); }

  // Qt's own words in its dialogs (file dialogs, message boxes) are Qt's
  // translations, loaded beside ours (Debian: qt6-translations-l10n,
  // qttranslations5-l10n; installed by setup).
  void qtsOwnDialogWordsAreChinese() {
    for (const auto& [context, word] : {std::pair{"QPlatformTheme", "Cancel"}, std::pair{"QPlatformTheme", "Close"},
                                        std::pair{"QFileDialog", "Look in:"}, std::pair{"QFileDialog", "File &name:"}}) {
      const QString shown = QCoreApplication::translate(context, word);
      QVERIFY2(shown != QString::fromLatin1(word) && englishIn(shown).isEmpty(),
               qPrintable(QString("%1 '%2' shows as '%3': Qt's translations are not loaded").arg(context, word, shown)));
    }
  }

  void aTemplateIsTranslatedWithItsVariablePartsAndTheRestKept() {
    QCOMPARE(ui::coreText(std::string("test point 2: no test point gave a delay")),
             QString::fromUtf8("测试点 2：没有测试点给出延迟"));
    QCOMPARE(ui::coreText(std::string("something the catalogue does not know")),
             QString("something the catalogue does not know"));
    QCOMPARE(ui::coreText(std::string("gyro channel (excess chi2 40 over 8 cells, 10.0 sigma)")),
             QString::fromUtf8("陀螺 通道（8 格上超出 chi2 40，10.0 σ）"));
  }

  void diagnosisOfACleanSession() { expectDiagnosisChinese(simulated({}, 21)); }

  // An X-only plan: the heading note says which sign was taken.
  void diagnosisOfAnXOnlyPlan() {
    const TestPlan plan = *presetPlan("quick");
    expectDiagnosisChinese(simulated({}, 2, plan), plan);
  }

  void diagnosisOfASessionWithAnEffect() {
    std::vector<std::unique_ptr<model::Effect>> e;
    e.push_back(diagnosis::makeEffect(diagnosis::EffectId::kFirstOrderLag, {3.0}));
    expectDiagnosisChinese(simulated(std::move(e), 22));
  }

  // The verdict's words when a kept effect closes little, and the frame's
  // alias of a named g-sensitivity (core/diagnosis, as the core writes them).
  void verdictWithoutAPartialExplanationAndTheFrameAlias() {
    expectChinese("the gap is significant and no effect in the library explains it: the best, table harmonic "
                  "distortion, closes only 5 % of the held-out gap and leaves a significant remainder in the gyro "
                  "channel (excess chi2 1421 over 100 cells, 100.5 sigma)");
    expectChinese("closes 100 % of the held-out gap; with the IMU's z axis up instead, a g-sensitivity of -59.34 "
                  "deg/h/g gives the same data as 40.00 deg/h/g in the frame used: an isotropic g-sensitivity adds "
                  "to the vertical Earth rate and swing data cannot tell them apart; check the IMU's mounting (a "
                  "static test with the IMU turned over separates them)");
    expectChinese("the table channel's harmonics are in the encoder's reading only: the share of the table's "
                  "harmonics the gyros do not see is 1.16 +- 0.11 (0 for a motion of the table, 1 for an encoder "
                  "reading error), 10.6 sigma from a motion; an encoder reading error (an eccentric grating, a "
                  "read-head error) is not in the library, whose table harmonic distortion is a motion and is kept "
                  "as the table channel's partial explanation");
    expectChinese("fits the table channel, but the gyros do not see its harmonics: a reading error, not a motion");
    expectChinese("closes 100 % of the held-out gap; an encoder reading error with the same harmonics is not "
                  "excluded: the share of the table's harmonics the gyros do not see is -0.12 +- 0.43 (0 for a "
                  "motion of the table, 1 for an encoder reading error); a second read head opposite the first, or "
                  "an autocollimator on the table, separates a reading error from a motion");
  }

  void effectNamesParametersAndUnits() {
    for (const auto& spec : diagnosis::effectLibrary()) {
      expectChinese(spec.name);
      for (const auto& p : spec.parameters) {
        expectChinese(p.name);
        expectChinese(p.unit);
      }
    }
  }

  void analysisVerdictsAndValidityChecks() {
    const Recording rec = simulated({}, 23);
    std::string storedJson;
    for (int sign : {1, -1}) {
      BenchConstants constants;
      constants.gyroSign = {sign, sign, sign};
      auto report = analysis::analyzeRecording(rec, constants);
      QVERIFY2(report.isOk(), report.status().toString().c_str());
      for (const auto& p : report->points) {
        for (const auto& c : p.checks) expectChinese(c.detail);
        for (const auto& w : p.warnings) expectChinese(w);
      }
      // The text report under Results, line by line.
      analysis::ReportContext context;
      context.source = "simulator, seed 1, as fast as possible, fogbench 0.1.0";
      context.trueLagMs = {0.5, 0.5, 0.5};
      expectEveryLineChinese(analysis::formatReportText(*report, context));
      for (double limit : {0.1, 10.0})
        for (const auto& why : analysis::judgeReport(*report, limit).reasons) expectChinese(why);
      // Where this version's analysis departs from a stored result (the
      // Results view's and the PDF's note): the result stored with sign +1
      // against the analysis with -1, and with points missing on either side.
      if (sign == 1) {
        storedJson = analysis::formatReportJson(*report, context);
        continue;
      }
      const session::StoredResult stored{1, "2026-11-26T07:00:00Z", "{}", storedJson, true};
      auto record = session::readStoredResult(stored, {});
      auto differences = session::differencesFromRecord(record, *report);
      QVERIFY(!differences.empty());
      analysis::DelayReport none = *report;
      none.points.clear();
      for (const auto& d : session::differencesFromRecord(record, none)) differences.push_back(d);
      record.points.clear();
      for (const auto& d : session::differencesFromRecord(record, *report)) differences.push_back(d);
      for (const auto& d : differences) expectChinese(d);
    }
  }

  void sourcesAndAStoppedRun() {
    for (double speed : {0.0, 1.0, 20.0}) {
      auto s = acquisition::SimulatorSource::create({}, diagnosis::blindCheckPlan(), speed);
      QVERIFY(s.isOk());
      expectChinese((*s)->description());
    }
    for (double speed : {0.0, 10.0}) expectChinese(acquisition::ReplaySource({}, speed, "run.fbs").description());
    auto source = acquisition::SimulatorSource::create({}, diagnosis::blindCheckPlan(), 1.0);
    QVERIFY(source.isOk());
    std::atomic<bool> stop{true};
    auto run = acquisition::acquire(**source, {}, &stop);
    QVERIFY2(run.isOk(), run.status().toString().c_str());
    QVERIFY(!run->incompleteReason.empty());
    expectChinese(run->incompleteReason);
    // A session whose recorder stopped without finishing it (the Sessions
    // list shows why).
    QTemporaryDir dir;
    const std::string path = dir.filePath("interrupted.fbs").toStdString();
    { auto writer = session::SessionWriter::create(path, SessionInfo{}); QVERIFY(writer.isOk()); }
    auto reader = session::SessionReader::open(path);
    QVERIFY(reader.isOk());
    QVERIFY(!(*reader)->complete());
    expectChinese((*reader)->incompleteReason());
  }

  // The gain check's words (issue 39), every kind: within the tolerance,
  // with the axis' fitted dynamics out, a gross factor (500x, 1/500, 0.25x),
  // a few percent with and without the hint on dynamics; and the one rule
  // for the fewest periods, as the plan and the analysis say it.
  void gainCheckAndMinimumPeriods() {
    analysis::TestPointResult p;
    p.joint.frequencyHz = 2.0;
    for (double ratio : {1.0, 499.9995, 0.002, 0.25, 1.02, 0.97}) {
      p.magnitudeRatio = ratio;
      expectChinese(analysis::gainCheck(p, {}, 0.01).detail);
      expectChinese(analysis::gainCheck(p, {0.97, "first_order"}, 0.01).detail);
    }
    TestPlan plan;
    plan.points.push_back({Axis::kX, 1.0, 3.0, 1.9, 1.0, 0.0});
    expectChinese(plan.validate(TurntableLimits{}).message());
    expectChinese("no test point gave a delay; test point 1: the record " + tooFewSwingPeriods(1.9));
    expectChinese("the table angle " + tooFewSwingPeriods(1.9) + " (at 1.0004 Hz)");
  }

  void unreadableSessionFiles() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string base = dir.path().toStdString();
    std::ofstream(base + "/empty.fbs").close();
    std::ofstream(base + "/text.fbs") << "not a session at all, just some text long enough to be read as a header";
    auto writer = session::SessionWriter::create(base + "/whole.fbs", {});
    QVERIFY(writer.isOk());
    QVERIFY((*writer)->finish(true, "").isOk());
    writer->reset();
    std::ifstream whole(base + "/whole.fbs", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(whole)), {});
    std::ofstream(base + "/cut.fbs", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::ofstream(base + "/page.fbs", std::ios::binary) << std::string(4096, '\0') << bytes.substr(4096);
    QCOMPARE(::mkfifo((base + "/pipe.fbs").c_str(), 0600), 0);
    QVERIFY(QFile::link("/dev/zero", dir.path() + "/zero.fbs"));
    for (const char* name : {"empty.fbs", "text.fbs", "cut.fbs", "page.fbs", "pipe.fbs", "zero.fbs", "missing.fbs", ""}) {
      auto r = session::SessionReader::open(base + "/" + name);
      QVERIFY2(!r.isOk(), name);
      if (std::string(name) == "page.fbs")
        QVERIFY2(r.status().message().find("first page") != std::string::npos, r.status().message().c_str());
      expectChinese(r.status().message(), dir.path());
    }
  }

  // A stream that does not state its pulse equivalent, with no bench
  // constant: as decoded (a run, a replay) and as a stored session reads it.
  void aStreamWithoutItsPulseEquivalent() {
    protocol::StreamDecoder decoder;
    protocol::ImuPayload imu;
    imu.pulses = {3, 0, 0};
    const std::vector<protocol::Frame> frames{{protocol::FrameType::kImu, 0, 100, imu},
                                              {protocol::FrameType::kImu, 1, 200, imu}};
    decoder.push(std::span<const protocol::Frame>(frames));
    auto rec = decoder.finish();
    QVERIFY(!rec.isOk());
    expectChinese(rec.status().message());

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.path().toStdString() + "/pulses.fbs";
    Recording pulses = simulated({}, 3);
    pulses.pulseEquivalentDeg = 0.0;  // as stored before the builder resolved it
    auto writer = session::SessionWriter::create(path, {});
    QVERIFY(writer.isOk());
    QVERIFY((*writer)->storeRecording(pulses).isOk());
    QVERIFY((*writer)->finish(true, "").isOk());
    writer->reset();
    auto reader = session::SessionReader::open(path);
    QVERIFY(reader.isOk());
    auto stored = (*reader)->recording();
    QVERIFY(!stored.isOk());
    expectChinese(stored.status().message(), dir.path());
  }

  // The C library's words for a system error, quoted inside a reason: a
  // session that cannot be created, and every errno a bench meets.
  void systemErrorsInsideReasons() {
    const std::string missing = "/nonexistent-fogbench-folder/s.fbs";
    auto writer = session::SessionWriter::create(missing, {});
    QVERIFY(!writer.isOk());
    expectChinese(writer.status().message(), QString::fromStdString(missing));
    for (int e : {EPERM, ENOENT, EINTR, EIO, ENXIO, EBADF, EAGAIN, EACCES, EBUSY, EEXIST, ENODEV, ENOTDIR, EISDIR, EINVAL,
                  ENFILE, EMFILE, ENOTTY, EFBIG, ENOSPC, EROFS, EPIPE, ENAMETOOLONG, ELOOP, EDQUOT, ECONNREFUSED,
                  ECONNRESET, ETIMEDOUT, EHOSTUNREACH, ENETUNREACH, EADDRINUSE, ENOTCONN, ETXTBSY, ENOMEM})
      expectChinese("cannot create session '/data/s.fbs': " + std::string(std::strerror(e)) +
                        "; check the folder exists and is writable",
                    "/data/s.fbs");
  }

  void planProblems() {
    // Every problem of points beyond each limit, and the plan-level refusals.
    const TurntableLimits limits;
    for (double f : {-1.0, 0.0, 5.0, 25.0})
      for (double a : {0.0, 30.0, 60.0})
        for (double d : {0.5, 1e5})
          for (bool still : {false, true}) {
            TestPoint p = still ? TestPoint::staticSegment(Axis::kY, d, -1.0) : TestPoint{};
            if (!still) p.frequencyHz = f, p.amplitudeDeg = a, p.durationS = d, p.settleS = -1.0;
            p.positionDeg[2] = 400.0;
            if (still) p.amplitudeDeg = a;
            else p.startPhaseDeg = std::numeric_limits<double>::infinity();
            for (const auto& problem : p.problems(limits)) expectChinese(problem.message);
          }
    TestPlan plan;
    expectChinese(plan.validate(limits).message());
    plan.points.push_back({Axis::kX, 1.0, 3.0, 4.0, 1.0, 0.0});
    plan.points.back().positionDeg[1] = 90.0;
    for (double rest : {0.0, 0.5, -1.0}) {
      plan.restBetweenS = rest;
      expectChinese(plan.validate(limits).message());
    }
    plan.restBetweenS = 5.0;
    plan.points.back().durationS = 90.0 * 3600.0;
    expectChinese(plan.validate(limits).message());
    plan.points.back().durationS = 4.0;
    plan.points.back().frequencyHz = 50.0;
    expectChinese(plan.validate(limits).message());
  }

  // What the Bode view and the report show of the frequency response: every
  // model's notes (correlations, a bandwidth beyond the points, a parameter
  // not told from 0) and why a model was left out.
  void frequencyResponseNotes() {
    ResponsePlanOptions o;
    o.lowestHz = 0.5;
    o.frequencies = 6;
    o.minDurationS = 3.0;
    const TestPlan plan = *responsePlan(TurntableLimits{}, o);
    model::SimConfig c;
    c.fog.rateFilterTimeConstantS = 2e-3;
    auto run = model::simulate(c, plan);
    QVERIFY(run.isOk());
    auto rec = protocol::decodeRecording(run->bytes);
    QVERIFY(rec.isOk());
    auto report = analysis::analyzeRecording(*rec, BenchConstants{});
    QVERIFY(report.isOk());
    const auto responses = analysis::analyzeResponses(*report);
    QCOMPARE(responses.size(), std::size_t(1));
    int notes = 0;
    for (const auto& m : responses.front().models)
      for (const auto& n : m.notes) {
        expectChinese(n);
        ++notes;
      }
    QVERIFY(notes > 0);
    for (const auto& s : responses.front().skipped) expectChinese(s);
    // Two points leave the second-order model out; a fit that found nothing says so.
    auto two = responses.front().points;
    two.resize(2);
    const auto few = analysis::analyzeResponse(two, Axis::kX, 5.0);
    QVERIFY(few.isOk());
    QCOMPARE(few->skipped.size(), std::size_t(1));
    expectChinese(few->skipped.front());
    // The choice rule's notes, with one and with two more parameters.
    expectChinese("AIC prefers it to the first-order lag by 0.742, but it lowers chi^2 by 2.74 only (1 more parameter "
                  "claimed at 9, 3 sigma): the first-order lag is chosen");
    expectChinese("AIC prefers it to the pure delay by 1.5, but it lowers chi^2 by 5.5 only (2 more parameters "
                  "claimed at 11.8, 3 sigma): the pure delay is chosen");
    // Each model judged (issue 40): why none fits, each reason in Chinese.
    auto bad = responses.front().points;
    bad[2].magnitude += 50.0 * bad[2].magnitudeStd;
    const auto none = analysis::analyzeResponse(bad, Axis::kX, 5.0);
    QVERIFY(none.isOk());
    QCOMPARE(none->chosen, -1);
    expectChinese(none->noModelReason);
    expectChinese("no model fits: none could be fitted");
    expectChinese("no model fits: the pure delay is not adequate: chi^2 1.1859e+08 on 38 dof, p = 0 below 0.001; "
                  "the second-order response is not admissible: tau_ms = -0.08786 ± 0.0037 ms is negative beyond 3 "
                  "sigma: the gyro would answer before the table moves");
    for (const char* why : {"T_ms = -0.5 ± 0.01 ms is negative beyond 3 sigma: a lead, not a lag",
                            "the low-frequency delay -0.05 ± 3.2e-06 ms is negative beyond 3 sigma: the gyro would answer before the table moves",
                            "zeta = 0.0001 ± 0.002 sits at its bound 0 within 3 sigma: the points do not place the resonance",
                            "fn_hz = 300 ± 400 Hz sits at its bound 0 within 3 sigma: the points do not place the resonance",
                            "the fit ran past zeta = 0: its poles are unstable (a lead that grows to the resonance)"})
      expectChinese(std::string("the second-order response is not admissible: ") + why);
    // Behind a stated table read delay (issue 40: tau is the lag behind the stamped angle).
    for (const char* why : {"tau_ms = -0.35 ± 0.01 ms is below -0.2 ms (minus the table read delay) beyond 3 sigma: "
                            "the gyro would answer before the table moves",
                            "the low-frequency delay -0.35 ± 0.01 ms is below -0.2 ms (minus the table read delay) "
                            "beyond 3 sigma: the gyro would answer before the table moves"})
      expectChinese(std::string("the first-order lag is not admissible: ") + why);
    for (const char* why : {"the fit did not converge in 50 iterations",
                            "the fit's sums are not finite numbers (a value in the data is far beyond its range)",
                            "the fit's parameters are not determined by the data", "the fit's covariance is not positive"})
      expectChinese(std::string("second_order: no fit from any of its 9 starting points (") + why +
                    "); the points may not hold such a filter");
    expectChinese("second_order: its best fit has 1/wn^2 = -0.00412 ms^2, not above 0: the points hold no "
                  "resonance (the first-order lag, T = 1.998 ms, is its limit)");
    expectChinese("second_order: its best fit has 1/wn^2 = -0.182 ms^2, not above 0: the points hold no resonance (a "
                  "magnitude droop without a filter's phase, as an average over about 2.09 ms would give)");
  }

  // The English GUI and PDF name the models' parameters by the symbols the
  // Chinese uses, not the JSON's keys (issue 41: "tau_ms and fn_hz
  // correlate" in the English PDF, "τ 与 fₙ" in the Chinese).
  void englishNamesParametersBySymbols() {
    QCOMPARE(ui::installTranslations(*qApp, "en"), QString("en"));
    const QString note = ui::coreText(
        "tau_ms and fn_hz correlate at -0.998: the points barely separate them (the low-frequency delay 1.1723 ± "
        "8.5e-06 ms is better determined than either)");
    const QString bound = ui::coreText("zeta = 0.0001 ± 0.002 sits at its bound 0 within 3 sigma; T_ms = -0.5 ± 0.01 ms");
    QCOMPARE(ui::installTranslations(*qApp, "zh_CN"), QString("zh_CN"));
    QVERIFY2(note.startsWith(QString::fromUtf8("τ and fₙ correlate at -0.998")), qPrintable(note));
    QVERIFY2(bound.startsWith(QString::fromUtf8("ζ = 0.0001")) && bound.contains("; T = -0.5"), qPrintable(bound));
    QVERIFY(!note.contains("_ms") && !note.contains("_hz"));
  }

  void noiseTermNames() {
    for (auto kind : {noise::NoiseTermKind::kQuantisation, noise::NoiseTermKind::kAngleRandomWalk,
                      noise::NoiseTermKind::kBiasInstability, noise::NoiseTermKind::kRateRandomWalk,
                      noise::NoiseTermKind::kRateRamp, noise::NoiseTermKind::kMarkov})
      expectChinese(noise::noiseTermName(kind));
  }

  void cleanup() {
    const QString all = failures_.join("\n");
    failures_.clear();
    QVERIFY2(all.isEmpty(), qPrintable(all));
  }

  void cleanupTestCase() { qInfo("%d core messages checked", checked_); }
};

}  // namespace

QTEST_MAIN(CoreTextTest)
#include "core_text_test.moc"
