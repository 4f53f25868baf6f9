// Results' frequency-response exports (issue 40): the points and the models
// as CSV (ResultView::exportResponseTo, ui/data_export.h), the Bode plot as
// one PNG, SVG or PDF (exportBodePlotTo), and the Bode view's points table
// with the phase's expanded uncertainty (k = 2). The files' content is read
// back and checked against the analysis shown, number for number; a models
// file that was not named in the dialog is never replaced; errors say why.

#include <QAction>
#include <QFile>
#include <QImage>
#include <QMenu>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>
#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/io/csv_export.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "ui/bode_view.h"
#include "ui/data_export.h"
#include "ui/result_view.h"
#include "ui/run_outcome.h"

namespace {

// A short response plan: 6 frequencies 0.5 Hz .. the table's limit, 3 s or 6 periods each.
fog::TestPlan shortPlan() {
  fog::ResponsePlanOptions o;
  o.lowestHz = 0.5;
  o.frequencies = 6;
  o.minDurationS = 3.0;
  return *fog::responsePlan(fog::TurntableLimits{}, o);
}

// The simulator's default chain, analysed with a stated read-delay
// uncertainty of 0.01 ms.
std::shared_ptr<fog::ui::RunOutcome> simulatedOutcome(const fog::TestPlan& plan) {
  fog::model::SimConfig config;
  config.seed = 7;
  auto run = fog::model::simulate(config, plan);
  if (!run) qFatal("simulate: %s", run.status().message().c_str());
  auto recording = fog::protocol::decodeRecording(run->bytes);
  if (!recording) qFatal("decode: %s", recording.status().message().c_str());
  fog::BenchConstants constants;
  constants.tableReadDelayStdMs = 0.01;
  auto outcome = std::make_shared<fog::ui::RunOutcome>();
  outcome->recording = std::move(*recording);
  outcome->report = fog::analysis::analyzeRecording(outcome->recording, constants);
  if (!outcome->report) qFatal("analyze: %s", outcome->report.status().message().c_str());
  outcome->info.source = "simulator, seed 7";
  fog::ui::completeOutcome(*outcome, "simulator, seed 7");
  return outcome;
}

QString readAll(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return QString();
  return QString::fromUtf8(f.readAll());
}

// A CSV as written: comment lines, then a header and rows (no quoted commas
// in the numeric columns read here).
struct Csv {
  QStringList comments;
  QStringList header;
  std::vector<QStringList> rows;
  QString at(std::size_t row, const QString& column) const { return rows[row][header.indexOf(column)]; }
  double number(std::size_t row, const QString& column) const {
    const std::string text = at(row, column).toStdString();
    double v = std::nan("");
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nan("");
    return v;
  }
};

Csv parse(const QString& text) {
  Csv csv;
  for (const QString& line : text.split('\n', Qt::SkipEmptyParts)) {
    if (line.startsWith('#')) {
      csv.comments << line;
    } else if (csv.header.isEmpty()) {
      csv.header = line.split(',');
    } else {
      // Quoted fields (the models' text columns) come last; only the
      // leading numeric ones are read by position.
      QStringList fields;
      QString field;
      bool quoted = false;
      for (int i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == '"') {
          if (quoted && i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
          else quoted = !quoted;
        } else if (c == ',' && !quoted) {
          fields << field;
          field.clear();
        } else {
          field += c;
        }
      }
      fields << field;
      csv.rows.push_back(fields);
    }
  }
  return csv;
}

QAction* menuAction(fog::ui::ResultView& view, const QString& text) {
  auto* button = view.findChild<QToolButton*>("exportButton");
  if (!button || !button->menu()) return nullptr;
  for (QAction* a : button->menu()->actions())
    if (a->text() == text) return a;
  return nullptr;
}

}  // namespace

class ResponseExportTest : public QObject {
  Q_OBJECT

 private:
  std::shared_ptr<fog::ui::RunOutcome> outcome_;

 private slots:
  void initTestCase() {
    outcome_ = simulatedOutcome(shortPlan());
    QCOMPARE(outcome_->responses.size(), std::size_t(1));
    QCOMPARE(outcome_->responses.front().points.size(), std::size_t(6));
    QCOMPARE(outcome_->responses.front().tableReadDelayStdMs, 0.01);
  }

  // The Export menu offers both; the points CSV holds every point with the
  // analysis' numbers exactly (shortest round trip), the phase against the
  // table's motion and its U (k = 2) with the read delay in the budget; the
  // models CSV every model with its parameters, the chosen one marked.
  void exportsThePointsAndTheModels() {
    fog::ui::ResultView view;
    view.resize(1300, 700);
    view.show();
    view.showOutcome(outcome_);
    QVERIFY(menuAction(view, "Frequency response: points and models (CSV)…"));
    QVERIFY(menuAction(view, "Bode plot (frequency response)…"));
    QTemporaryDir dir;
    const QString points = dir.filePath("resp.csv");
    QSignalSpy exported(&view, &fog::ui::ResultView::exported);
    QCOMPARE(view.exportResponseTo(points), QString());
    const QString models = dir.filePath("resp-models.csv");
    QCOMPARE(fog::ui::responseModelsPath(points), models);
    QCOMPARE(exported.count(), 2);

    const auto& r = outcome_->responses.front();
    const Csv p = parse(readAll(points));
    QCOMPARE(p.header.join(','),
             QString("axis,test_point,frequency_hz,magnitude,magnitude_std,magnitude_db,magnitude_db_std,phase_deg,"
                     "phase_std_deg,lag_ms,lag_std_ms,magnitude_phase_cov_deg,harmonic_fraction,"
                     "phase_vs_table_motion_deg,phase_standard_uncertainty_deg,coverage_factor,"
                     "phase_expanded_uncertainty_deg,phase_expanded_uncertainty_ms"));
    QCOMPARE(p.rows.size(), r.points.size());
    QVERIFY(p.comments.filter("source: simulator, seed 7").size() == 1);
    QVERIFY2(p.comments.filter("X axis: table read delay 0.05 ms, standard uncertainty 0.01 ms").size() == 1,
             qPrintable(p.comments.join('\n')));
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const auto& point = r.points[i];
      const auto c = fog::analysis::certifiedPhase(point, r);
      QCOMPARE(p.at(i, "axis"), QString("X"));
      QCOMPARE(p.at(i, "test_point").toInt(), point.index + 1);
      // Exactly the analysis' doubles, in the exporter's shortest form.
      QCOMPARE(p.at(i, "frequency_hz"), QString::fromStdString(fog::io::formatDouble(point.frequencyHz)));
      QCOMPARE(p.number(i, "frequency_hz"), point.frequencyHz);
      QCOMPARE(p.number(i, "magnitude"), point.magnitude);
      QCOMPARE(p.number(i, "phase_deg"), point.phaseDeg);
      QCOMPARE(p.number(i, "lag_std_ms"), point.lagStdMs);
      QCOMPARE(p.number(i, "phase_vs_table_motion_deg"), c.phaseDeg);
      QCOMPARE(p.number(i, "coverage_factor"), 2.0);
      QCOMPARE(p.number(i, "phase_expanded_uncertainty_deg"), c.expandedDeg);
      QCOMPARE(p.number(i, "phase_expanded_uncertainty_ms"), c.expandedMs);
      // The closed form: U = 2 sqrt(sigma_lag^2 + u_d^2) ms; against the
      // motion the gyro is the read delay later than against the stamps.
      QVERIFY(std::abs(p.number(i, "phase_expanded_uncertainty_ms") - 2.0 * std::hypot(point.lagStdMs, 0.01)) < 1e-12);
      QVERIFY(std::abs(p.number(i, "phase_vs_table_motion_deg") -
                       (point.phaseDeg - 360.0 * point.frequencyHz * 0.05e-3)) < 1e-9);
      QVERIFY(p.number(i, "phase_expanded_uncertainty_ms") >= 0.02);
    }

    const Csv m = parse(readAll(models));
    QCOMPARE(m.header.mid(0, 12).join(','), QString("axis,model,chosen,adequate,admissible,chi_square,dof,p_value,aic,"
                                                    "bic,K,K_std"));
    QCOMPARE(m.header.size(), 30);
    QCOMPARE(m.rows.size(), r.models.size());
    int chosen = 0;
    for (std::size_t i = 0; i < r.models.size(); ++i) {
      const auto& model = r.models[i];
      QCOMPARE(m.rows[i].size(), m.header.size());
      QCOMPARE(m.at(i, "model"), QString(fog::analysis::responseModelName(model.kind)));
      QCOMPARE(m.at(i, "chosen") == "true", static_cast<int>(i) == r.chosen);
      chosen += m.at(i, "chosen") == "true";
      QCOMPARE(m.at(i, "adequate") == "true", model.adequate);
      QCOMPARE(m.number(i, "chi_square"), model.chiSquare);
      QCOMPARE(m.at(i, "dof").toInt(), model.dof);
      QCOMPARE(m.number(i, "K"), model.parameters[0].value);
      QCOMPARE(m.number(i, "tau_ms"), model.parameters[1].value);
      QCOMPARE(m.number(i, "tau_ms_std"), model.parameters[1].stdDev);
      QCOMPARE(m.number(i, "group_delay_at_hz"), 5.0);
      QCOMPARE(m.number(i, "group_delay_ms"), model.groupDelayMs.value);
      if (model.kind == fog::analysis::ResponseModelKind::kDelay) {
        QVERIFY(m.at(i, "T_ms").isEmpty());
        QVERIFY(m.at(i, "bandwidth_hz").isEmpty());  // a pure delay has none
        QVERIFY(m.at(i, "correlations").startsWith("K/tau_ms "));
      }
      if (model.kind == fog::analysis::ResponseModelKind::kFirstOrder) {
        QCOMPARE(m.number(i, "T_ms"), model.parameters[2].value);
        QVERIFY(m.at(i, "fn_hz").isEmpty());
        QCOMPARE(m.number(i, "bandwidth_hz"), model.bandwidthHz->value);
      }
    }
    QCOMPARE(chosen, r.chosen >= 0 ? 1 : 0);
    QCOMPARE(m.comments.filter(r.chosen >= 0 ? "# X axis: chosen " : "# X axis: no model fits").size(), 1);
  }

  // The models' file beside the points was not named in the dialog: one
  // already there is never replaced, and then nothing is written at all.
  void neverReplacesAFileTheUserDidNotName() {
    fog::ui::ResultView view;
    view.showOutcome(outcome_);
    QTemporaryDir dir;
    const QString points = dir.filePath("r.csv"), models = dir.filePath("r-models.csv");
    for (const auto& [path, text] : {std::pair{points, QByteArray("points kept\n")}, std::pair{models, QByteArray("models kept\n")}}) {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(text);
    }
    const QString why = view.exportResponseTo(points);
    QVERIFY2(why.contains("r-models.csv") && why.contains("already exists") && why.contains("not replaced"),
             qPrintable(why));
    QCOMPARE(readAll(points), QString("points kept\n"));
    QCOMPARE(readAll(models), QString("models kept\n"));
    // Without the models' file the named one is replaced (the dialog asked).
    QVERIFY(QFile::remove(models));
    QCOMPARE(view.exportResponseTo(points), QString());
    QVERIFY(readAll(points).startsWith("# fogbench frequency response: the points"));
    QVERIFY(readAll(models).startsWith("# fogbench frequency response: the models"));
    // A folder that cannot be written: said in words, naming the file.
    const QString nowhere = dir.filePath("no/such/folder/r.csv");
    const QString cannot = view.exportResponseTo(nowhere);
    QVERIFY2(cannot.startsWith("Cannot create") && cannot.contains("r.csv"), qPrintable(cannot));
  }

  // The Bode plot as one image: magnitude over phase, drawn (not blank),
  // at the stated size; SVG and PDF are documents of their kind.
  void exportsTheBodePlotAsAnImage() {
    fog::ui::ResultView view;
    view.resize(1300, 700);
    view.show();
    view.showOutcome(outcome_);
    QTemporaryDir dir;
    const QString png = dir.filePath("bode.png");
    QCOMPARE(view.exportBodePlotTo(png), QString());
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1600, 1280));
    // Both halves drawn: dark pixels (axes, labels, points) in each.
    for (int half = 0; half < 2; ++half) {
      int dark = 0;
      for (int y = half * 640; y < (half + 1) * 640; y += 2)
        for (int x = 0; x < image.width(); x += 2) dark += qGray(image.pixel(x, y)) < 128;
      QVERIFY2(dark > 500, qPrintable(QString("half %1: %2 dark pixels").arg(half).arg(dark)));
    }
    const QString svg = dir.filePath("bode.svg");
    QCOMPARE(view.exportBodePlotTo(svg), QString());
    const QString svgText = readAll(svg);
    QVERIFY(svgText.contains("<svg"));
    QVERIFY(svgText.contains("phase"));  // the phase plot's axis title
    const QString pdf = dir.filePath("bode.pdf");
    QCOMPARE(view.exportBodePlotTo(pdf), QString());
    QVERIFY(readAll(pdf).startsWith("%PDF"));
    const QString why = view.exportBodePlotTo(dir.filePath("bode.bmp"));
    QVERIFY2(why.contains("choose a .png, .svg or .pdf file name"), qPrintable(why));
  }

  // The Bode view lists every point with the phase against the table's
  // motion and its U (k = 2) in degrees and ms.
  void thePointsTableStatesThePhaseUncertainty() {
    fog::ui::BodeView view;
    view.showResponses(outcome_->responses, "none");
    const auto& r = outcome_->responses.front();
    QTableWidget* t = view.pointTable();
    QCOMPARE(t->rowCount(), static_cast<int>(r.points.size()));
    QCOMPARE(t->horizontalHeaderItem(6)->text(), QString("U (k = 2), °"));
    QCOMPARE(t->horizontalHeaderItem(7)->text(), QString("U (k = 2), ms"));
    for (int row = 0; row < t->rowCount(); ++row) {
      const auto c = fog::analysis::certifiedPhase(r.points[static_cast<std::size_t>(row)], r);
      QCOMPARE(t->item(row, 6)->text().toDouble(), QString::number(c.expandedDeg, 'g', 2).toDouble());
      QCOMPARE(t->item(row, 7)->text().toDouble(), QString::number(c.expandedMs, 'g', 2).toDouble());
      QVERIFY(t->item(row, 7)->toolTip().contains("table read delay"));
    }
  }

  // A result without a response: nothing to export, and why.
  void withoutAResponseNothingIsWritten() {
    fog::TestPlan one;
    one.points.push_back({fog::Axis::kX, 1.0, 3.0, 6.0, 1.0, 0.0});
    auto outcome = simulatedOutcome(one);
    QVERIFY(outcome->responses.empty());
    fog::ui::ResultView view;
    view.showOutcome(outcome);
    QTemporaryDir dir;
    const QString why = view.exportResponseTo(dir.filePath("r.csv"));
    QVERIFY2(why.startsWith("There is no frequency response to export"), qPrintable(why));
    QVERIFY(!QFile::exists(dir.filePath("r.csv")));
    QVERIFY(!QFile::exists(dir.filePath("r-models.csv")));
    QVERIFY(view.exportBodePlotTo(dir.filePath("b.png")).startsWith("There is no Bode plot to export"));
    QVERIFY(!QFile::exists(dir.filePath("b.png")));
  }
};

QTEST_MAIN(ResponseExportTest)
#include "response_export_test.moc"
