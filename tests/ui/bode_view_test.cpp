// The Bode view (ui/bode_view.h) on responses the simulator made with a
// first-order rate filter: every point and the chosen model drawn on both
// plots, the model table, the measuring cursors and their readout, the
// message when there is no response, Compare's A, B and B − A, and Results
// opening a response plan's result on its Bode plot.

#include <QComboBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QtTest>
#include <cmath>
#include <memory>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_scale_div.h>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "ui/bode_view.h"
#include "ui/plots/plot_interaction.h"
#include "ui/result_view.h"
#include "ui/run_outcome.h"

using fog::analysis::ResponseAnalysis;

namespace {

// A shortened response plan: 8 frequencies 0.5 Hz .. the table's limit.
fog::TestPlan shortPlan() {
  fog::ResponsePlanOptions o;
  o.lowestHz = 0.5;
  o.frequencies = 8;
  o.minDurationS = 3.0;
  return *fog::responsePlan(fog::TurntableLimits{}, o);
}

struct Simulated {
  fog::Recording recording;
  fog::analysis::DelayReport report;
};

Simulated simulate(double filterMs, std::uint64_t seed) {
  fog::model::SimConfig config;
  config.seed = seed;
  config.fog.rateFilterTimeConstantS = filterMs * 1e-3;
  auto run = fog::model::simulate(config, shortPlan());
  if (!run) qFatal("simulate: %s", run.status().message().c_str());
  auto recording = fog::protocol::decodeRecording(run->bytes);
  auto report = fog::analysis::analyzeRecording(*recording, fog::BenchConstants{});
  if (!report) qFatal("analyze: %s", report.status().message().c_str());
  return {std::move(*recording), std::move(*report)};
}

// The response of an exact delay + first-order lag (tau, T) at the points'
// frequencies, with their uncertainties: one the models describe to the
// last digit, so that its first order is adequate and chosen. (The
// simulator's own 2-ms filter is not yet a first order at its noise level:
// issue 40; the view is tested on a response whose model is known.)
ResponseAnalysis exactFirstOrder(std::vector<fog::analysis::ResponsePoint> points, double tauMs, double tMs) {
  for (auto& p : points) {
    const double w = 2.0 * M_PI * p.frequencyHz;
    p.magnitude = 1.0 / std::sqrt(1.0 + std::pow(w * tMs * 1e-3, 2));
    p.magnitudeDb = 20.0 * std::log10(p.magnitude);
    p.phaseDeg = -(w * tauMs * 1e-3 + std::atan(w * tMs * 1e-3)) * 180.0 / M_PI;
    p.lagMs = -p.phaseDeg / 360.0 / p.frequencyHz * 1e3;
    p.magnitudePhaseCovDeg = 0.0;
  }
  auto r = fog::analysis::analyzeResponse(points, fog::Axis::kX, 5.0);
  if (!r) qFatal("analyzeResponse: %s", r.status().message().c_str());
  return std::move(*r);
}

template <typename Item>
std::vector<const Item*> items(QwtPlot* plot, int rtti) {
  std::vector<const Item*> out;
  for (auto* item : plot->itemList(rtti)) out.push_back(static_cast<const Item*>(item));
  return out;
}

}  // namespace

class BodeViewTest : public QObject {
  Q_OBJECT

 private:
  Simulated a_, b_;
  std::vector<ResponseAnalysis> ra_, rb_;

 private slots:
  void initTestCase() {
    a_ = simulate(0.0, 1);
    b_ = simulate(2.0, 2);
    ra_ = fog::analysis::analyzeResponses(a_.report);
    QCOMPARE(ra_.size(), std::size_t(1));
    QVERIFY(ra_.front().chosen >= 0);  // the simulator's pure delay: a delay model fits
    const auto measured = fog::analysis::analyzeResponses(b_.report);
    QCOMPARE(measured.size(), std::size_t(1));
    rb_ = {exactFirstOrder(measured.front().points, 0.466, 2.0)};
    QVERIFY(rb_.front().chosen >= 0);
    QCOMPARE(ra_.front().points.size(), std::size_t(8));
  }

  // Every point with its error bar and the chosen model on both plots, on a
  // log frequency axis spanning the points; one row per fitted model, the
  // chosen one bold.
  void drawsThePointsAndTheChosenModel() {
    fog::ui::BodeView view;
    view.resize(700, 600);
    view.show();
    view.showResponses(rb_, "none");
    QVERIFY(view.plotShown());
    QVERIFY(view.axisCombo()->isHidden());  // one axis
    const auto& r = rb_.front();
    for (QwtPlot* plot : {view.magnitudePlot(), view.phasePlot()}) {
      const auto curves = items<QwtPlotCurve>(plot, QwtPlotItem::Rtti_PlotCurve);
      QCOMPARE(curves.size(), std::size_t(2));  // points, model
      QCOMPARE(curves[0]->dataSize(), r.points.size());
      QVERIFY(curves[1]->dataSize() >= 100);
      const auto bars = items<QwtPlotIntervalCurve>(plot, QwtPlotItem::Rtti_PlotIntervalCurve);
      QCOMPARE(bars.size(), std::size_t(1));
      QCOMPARE(bars[0]->dataSize(), r.points.size());
      const QwtScaleDiv& x = plot->axisScaleDiv(QwtPlot::xBottom);
      QVERIFY(x.lowerBound() < r.points.front().frequencyHz && x.lowerBound() > 0.3);
      QVERIFY(x.upperBound() > r.points.back().frequencyHz && x.upperBound() < 2.0 * r.points.back().frequencyHz);
    }
    // The magnitude points are the analysis' dB values; the phase its degrees.
    const auto magnitude = items<QwtPlotCurve>(view.magnitudePlot(), QwtPlotItem::Rtti_PlotCurve)[0];
    const auto phase = items<QwtPlotCurve>(view.phasePlot(), QwtPlotItem::Rtti_PlotCurve)[0];
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      QCOMPARE(magnitude->sample(static_cast<int>(i)).y(), r.points[i].magnitudeDb);
      QCOMPARE(phase->sample(static_cast<int>(i)).y(), r.points[i].phaseDeg);
    }
    // A 2-ms first-order lag: the chosen model is the first order, and
    // the high end of the magnitude has dropped (20 log10 of 1/sqrt(1 + (wT)^2)).
    QCOMPARE(r.models[static_cast<std::size_t>(r.chosen)].kind, fog::analysis::ResponseModelKind::kFirstOrder);
    QVERIFY(r.points.back().magnitudeDb < -0.01);
    QCOMPARE(view.modelTable()->rowCount(), static_cast<int>(r.models.size()));
    for (int row = 0; row < view.modelTable()->rowCount(); ++row)
      QCOMPARE(view.modelTable()->item(row, 1)->font().bold(), row == r.chosen);
    QVERIFY2(view.summaryText().contains("(chosen)"), qPrintable(view.summaryText()));
  }

  // Cursors on the frequency axis: f at each, Δf, and each curve's value.
  void cursorsReadFrequencyAndValues() {
    fog::ui::BodeView view;
    view.resize(700, 600);
    view.show();
    view.showResponses(rb_, "none");
    auto* interaction = view.magnitudeInteraction();
    interaction->placeCursor(1.0);
    interaction->placeCursor(4.0);
    const QString readout = interaction->readout();
    QVERIFY2(readout.contains("A: f = 1") && readout.contains("B: f = 4"), qPrintable(readout));
    QVERIFY2(readout.contains("Δf = 3"), qPrintable(readout));
    const auto& m = rb_.front().models[static_cast<std::size_t>(rb_.front().chosen)];
    const double at4 = 20.0 * std::log10(m.magnitudeAt(4.0));
    bool found = false;
    for (const auto& [name, value] : interaction->valuesAt(4.0))
      if (name.startsWith("model")) found = std::abs(value - at4) < 1e-12;
    QVERIFY2(found, qPrintable(readout));
    // The two plots share the frequency axis.
    view.magnitudePlot()->setAxisScale(QwtPlot::xBottom, 1.0, 3.0);
    view.magnitudePlot()->replot();
    QCOMPARE(view.phasePlot()->axisScaleDiv(QwtPlot::xBottom).lowerBound(), 1.0);
    QCOMPARE(view.phasePlot()->axisScaleDiv(QwtPlot::xBottom).upperBound(), 3.0);
  }

  // Issue 40: when no model is adequate and admissible none is chosen; the
  // view draws the points alone, says "no model fits" and why, and shows
  // each model's p-value (rejected ones marked) with none bold.
  void whenNoModelFitsThePointsShowAlone() {
    auto points = rb_.front().points;
    points[3].magnitude += 50.0 * points[3].magnitudeStd;
    auto r = fog::analysis::analyzeResponse(points, fog::Axis::kX, 5.0);
    QVERIFY(r.isOk());
    QCOMPARE(r->chosen, -1);
    QVERIFY(!r->models.empty());
    fog::ui::BodeView view;
    view.resize(700, 600);
    view.show();
    view.showResponses({*r}, "none");
    QVERIFY(view.plotShown());
    for (QwtPlot* plot : {view.magnitudePlot(), view.phasePlot()})
      QCOMPARE(items<QwtPlotCurve>(plot, QwtPlotItem::Rtti_PlotCurve).size(), std::size_t(1));  // the points only
    QVERIFY2(view.summaryText().contains("no model fits"), qPrintable(view.summaryText()));
    QVERIFY2(view.summaryText().contains("is not adequate: chi^2"), qPrintable(view.summaryText()));
    QVERIFY2(!view.summaryText().contains("(chosen)"), qPrintable(view.summaryText()));
    QCOMPARE(view.modelTable()->rowCount(), static_cast<int>(r->models.size()));
    for (int row = 0; row < view.modelTable()->rowCount(); ++row) {
      QVERIFY(!view.modelTable()->item(row, 1)->font().bold());
      QVERIFY2(view.modelTable()->item(row, 3)->text().contains("rejected"), qPrintable(view.modelTable()->item(row, 3)->text()));
    }
    // The cursors' readout has the points and no model.
    for (const auto& [name, value] : view.magnitudeInteraction()->valuesAt(4.0)) QVERIFY(!name.startsWith("model"));
  }

  void withoutAResponseOnlyTheReasonShows() {
    fog::ui::BodeView view;
    view.showResponses({}, fog::ui::responseMissingText(a_.report));
    QVERIFY(!view.plotShown());
    fog::analysis::DelayReport onePoint = a_.report;
    onePoint.points.resize(1);
    const QString why = fog::ui::responseMissingText(onePoint);
    QVERIFY2(why.contains("X axis: 1") && why.contains("--preset response"), qPrintable(why));
  }

  // Compare: A and B with their models, and B − A at the frequencies both have.
  void compareDrawsBothAndTheirDifference() {
    fog::ui::BodeView view;
    view.resize(700, 600);
    view.show();
    view.showComparison(ra_, rb_, "A", "C", "none");
    QVERIFY(view.plotShown());
    QCOMPARE(view.series().size(), std::size_t(3));
    QCOMPARE(view.series()[2].name, QString("C − A"));
    const auto& d = view.series()[2].points;
    QCOMPARE(d.size(), std::size_t(8));
    for (std::size_t i = 0; i < d.size(); ++i)
      QVERIFY(std::abs(d[i].phaseDeg - (rb_.front().points[i].phaseDeg -
                                        ra_.front().points[i].phaseDeg * d[i].frequencyHz /
                                            ra_.front().points[i].frequencyHz)) < 1e-12);
    // Points of A, B and the difference; models of A and B.
    QCOMPARE(items<QwtPlotCurve>(view.phasePlot(), QwtPlotItem::Rtti_PlotCurve).size(), std::size_t(5));
    QCOMPARE(view.modelTable()->rowCount(), static_cast<int>(ra_.front().models.size() + rb_.front().models.size()));
    // Nothing in common: the reason.
    view.showComparison(ra_, {}, "A", "B", "no common axis");
    QVERIFY(!view.plotShown());
  }

  // Results: a response plan's result opens on its Bode plot, drawn from the
  // outcome's one analysis.
  void resultsOpenAResponseOnItsBodePlot() {
    auto outcome = std::make_shared<fog::ui::RunOutcome>();
    outcome->recording = b_.recording;
    outcome->report = b_.report;
    fog::ui::completeOutcome(*outcome, "test");
    QCOMPARE(outcome->responses.size(), std::size_t(1));
    fog::ui::ResultView view;
    view.resize(1300, 700);
    view.show();
    view.showOutcome(outcome);
    QCOMPARE(view.leftTabs()->currentWidget(), static_cast<QWidget*>(view.bodeView()));
    QVERIFY(view.bodeView()->plotShown());
    QCOMPARE(view.bodeView()->series().front().points.size(), outcome->responses.front().points.size());
  }
};

QTEST_MAIN(BodeViewTest)
#include "bode_view_test.moc"
