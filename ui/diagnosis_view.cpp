#include "ui/diagnosis_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFontDatabase>
#include <QFontMetrics>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <qwt_color_map.h>
#include <qwt_column_symbol.h>
#include <qwt_legend.h>
#include <qwt_matrix_raster_data.h>
#include <qwt_plot.h>
#include <qwt_plot_barchart.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_multi_barchart.h>
#include <qwt_plot_spectrogram.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_widget.h>
#include <qwt_text.h>

#include "ui/core_text.h"
#include "ui/language/language.h"
#include "ui/plots/plot_interaction.h"

namespace fog::ui {

namespace {

// Smallest font of the gap map's labels.
constexpr double kMinLabelPt = 9.0;

constexpr double kZRange = 5.0;  // the heat map saturates at |z| = 5
const QColor kReal(31, 119, 180);
const QColor kSim(255, 127, 14);

// Integer positions named from a list (rows and columns of the heat map,
// effects of the bar chart).
class NamedScaleDraw : public QwtScaleDraw {
 public:
  explicit NamedScaleDraw(QStringList names) : names_(std::move(names)) {}
  QwtText label(double v) const override {
    const long i = std::lround(v);
    if (std::abs(v - static_cast<double>(i)) > 1e-6 || i < 0 || i >= names_.size()) return QwtText();
    return QwtText(names_[static_cast<int>(i)]);
  }

 private:
  QStringList names_;
};

// Bars of the effects that were kept stand out.
class ShrinkChart : public QwtPlotBarChart {
 public:
  explicit ShrinkChart(std::vector<bool> kept) : kept_(std::move(kept)) {}
  QwtColumnSymbol* specialSymbol(int index, const QPointF&) const override {
    auto* s = new QwtColumnSymbol(QwtColumnSymbol::Box);
    const bool kept = index >= 0 && static_cast<std::size_t>(index) < kept_.size() && kept_[static_cast<std::size_t>(index)];
    s->setPalette(QPalette(kept ? QColor(44, 160, 44) : QColor(170, 170, 170)));
    s->setLineWidth(0);
    return s;
  }

 private:
  std::vector<bool> kept_;
};

QwtPlot* makePlot(const QString& title, const QString& x, const QString& y) {
  auto* p = new QwtPlot();
  p->setTitle(title);
  p->setAxisTitle(QwtPlot::xBottom, x);
  p->setAxisTitle(QwtPlot::yLeft, y);
  p->setCanvasBackground(Qt::white);
  p->setMinimumSize(300, 220);
  return p;
}

QString axisLetter(int a) { return a < 0 ? QString() : QString(QChar('X' + a)); }

// Calls `onResize` whenever the watched widget is resized.
class ResizeHook : public QObject {
 public:
  ResizeHook(QObject* watched, std::function<void()> onResize) : QObject(watched), onResize_(std::move(onResize)) {
    watched->installEventFilter(this);
  }
  bool eventFilter(QObject*, QEvent* event) override {
    if (event->type() == QEvent::Resize) onResize_();
    return false;
  }

 private:
  std::function<void()> onResize_;
};

}  // namespace

DiagnosisView::DiagnosisView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buildVerdictRow());
  layout->addLayout(buildNoiseRow());
  layout->addWidget(buildProgressRow());
  progressRow_->hide();
  layout->addWidget(buildResultStack(buildPlots()), 1);

  gapMap_ = new QwtPlotSpectrogram();
  gapMap_->setRenderThreadCount(1);
  gapMap_->attach(gapMapPlot_);
  connect(pointCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &DiagnosisView::showPoint);
  showMessage(tr("Run or open a session, then press Diagnose in the Results view."));
}

// The verdict, and the test point the curves and the spectrum show.
QHBoxLayout* DiagnosisView::buildVerdictRow() {
  auto* top = new QHBoxLayout();
  verdict_ = new QLabel();
  verdict_->setObjectName("diagnosisVerdict");
  verdict_->setWordWrap(true);
  verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  new ResizeHook(verdict_, [this] { fitVerdictHeight(); });
  top->addWidget(verdict_, 1);
  pointLabel_ = new QLabel(tr("Test point"));
  top->addWidget(pointLabel_);
  pointCombo_ = new QComboBox();
  pointCombo_->setObjectName("diagnosisPointCombo");
  pointCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  top->addWidget(pointCombo_);
  return top;
}

// What the replays take for the IMU's bias instability: one recording
// cannot tell a wander of the bias from a drift or step, so the operator
// states it from the IMU's static noise test (Noise view).
QHBoxLayout* DiagnosisView::buildNoiseRow() {
  auto* noiseRow = new QHBoxLayout();
  const model::FogParams nominal;
  QSettings settings;
  settings.beginGroup("diagnosis");
  noiseStated_ = new QCheckBox(tr("IMU bias instability known:"));
  noiseStated_->setObjectName("noiseStatedBox");
  noiseStated_->setChecked(settings.value("bias_instability_stated", false).toBool());
  noiseStated_->setToolTip(tr("The IMU's bias instability from its static noise test (Noise view: Markov sigma and "
                              "correlation time). Unchecked, the diagnosis assumes %1 °/h over %2 s, and a bias drift "
                              "or step smaller than such a wander is not resolved.")
                               .arg(nominal.biasInstabilityDegPerH)
                               .arg(nominal.biasCorrelationS));
  instability_ = new QDoubleSpinBox();
  instability_->setObjectName("instabilitySpin");
  instability_->setRange(0.0, 3600.0);
  instability_->setDecimals(4);
  instability_->setSuffix(tr(" °/h"));
  instability_->setValue(settings.value("bias_instability_deg_h", nominal.biasInstabilityDegPerH).toDouble());
  correlation_ = new QDoubleSpinBox();
  correlation_->setObjectName("correlationSpin");
  correlation_->setRange(1.0, 1e6);
  correlation_->setDecimals(0);
  correlation_->setPrefix(tr("over "));
  correlation_->setSuffix(tr(" s"));
  correlation_->setValue(settings.value("bias_correlation_s", nominal.biasCorrelationS).toDouble());
  auto enable = [this](bool on) {
    instability_->setEnabled(on);
    correlation_->setEnabled(on);
  };
  enable(noiseStated_->isChecked());
  connect(noiseStated_, &QCheckBox::toggled, this, enable);
  auto remember = [this] {
    QSettings q;
    q.beginGroup("diagnosis");
    q.setValue("bias_instability_stated", noiseStated_->isChecked());
    q.setValue("bias_instability_deg_h", instability_->value());
    q.setValue("bias_correlation_s", correlation_->value());
  };
  connect(noiseStated_, &QCheckBox::toggled, this, remember);
  connect(instability_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, remember);
  connect(correlation_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, remember);
  noiseRow->addWidget(noiseStated_);
  noiseRow->addWidget(instability_);
  noiseRow->addWidget(correlation_);
  noiseRow->addStretch(1);
  return noiseRow;
}

// Progress of a running diagnosis, with Cancel.
QWidget* DiagnosisView::buildProgressRow() {
  progressRow_ = new QWidget();
  progressRow_->setObjectName("diagnosisProgressRow");
  auto* progressLayout = new QHBoxLayout(progressRow_);
  progressLayout->setContentsMargins(0, 0, 0, 0);
  progress_ = new QProgressBar();
  progress_->setObjectName("diagnosisProgress");
  progress_->setRange(0, 1000);
  progress_->setTextVisible(true);
  progress_->setFormat(QStringLiteral("%p%"));
  progressLayout->addWidget(progress_, 2);
  stage_ = new QLabel();
  stage_->setObjectName("diagnosisStage");
  stage_->setMinimumWidth(120);
  progressLayout->addWidget(stage_, 1);
  cancel_ = new QPushButton(tr("Cancel"));
  cancel_->setObjectName("cancelDiagnosisButton");
  cancel_->setToolTip(tr("Stop the diagnosis; nothing is kept of it"));
  progressLayout->addWidget(cancel_);
  connect(cancel_, &QPushButton::clicked, this, [this] {
    if (state_ != State::kRunning) return;
    cancel_->setEnabled(false);
    stage_->setText(tr("cancelling …"));
    emit cancelRequested();
  });
  return progressRow_;
}

// The four plots in a grid, each with its interaction.
QWidget* DiagnosisView::buildPlots() {
  curvePlot_ = makePlot(tr("Gyro residual: real and simulated"), tr("time from the record's middle (s)"),
                        tr("residual (arcsec)"));
  curvePlot_->setObjectName("diagnosisCurvePlot");
  curvePlot_->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  gapMapPlot_ = makePlot(tr("Gap map: z against the simulator's spread"), QString(), QString());
  gapMapPlot_->setObjectName("gapMapPlot");
  spectrumPlot_ = makePlot(tr("Residual spectrum"), tr("harmonic of the swing frequency"),
                           tr("relative to the fundamental (ppm)"));
  spectrumPlot_->setObjectName("spectrumPlot");
  spectrumPlot_->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  // Bars across, names down the left: the effect names are long, and upright
  // under the bars they squashed the plot to a strip.
  shrinkPlot_ = makePlot(tr("Held-out shrink per candidate effect"), tr("held-out gap closed (%)"), QString());
  shrinkPlot_->setObjectName("shrinkPlot");
  // One interaction on every plot; measuring cursors on the residual curves.
  PlotInteraction::Options curveOptions;
  curveOptions.cursors = true;
  curveOptions.yUnit = tr("″");
  curveInteraction_ = new PlotInteraction(curvePlot_, curveOptions);
  curveInteraction_->setValuesAt([this](double t) {
    PlotInteraction::Values values;
    for (const QwtPlotItem* item : curvePlot_->itemList(QwtPlotItem::Rtti_PlotCurve)) {
      const auto* curve = static_cast<const QwtPlotCurve*>(item);
      const int n = static_cast<int>(curve->dataSize());
      if (n < 2 || t < curve->sample(0).x() || t > curve->sample(n - 1).x()) continue;
      int hi = 1;
      while (hi + 1 < n && curve->sample(hi).x() < t) ++hi;
      const QPointF a = curve->sample(hi - 1), b = curve->sample(hi);
      const double v = b.x() > a.x() ? a.y() + (b.y() - a.y()) * (t - a.x()) / (b.x() - a.x()) : b.y();
      values.push_back({curve->title().text(), v});
    }
    return values;
  });
  PlotInteraction::Options plain;
  plain.timeAxis = false;
  gapMapInteraction_ = new PlotInteraction(gapMapPlot_, plain);
  new ResizeHook(gapMapPlot_->canvas(), [this] { fitGapMapColumns(); });
  spectrumInteraction_ = new PlotInteraction(spectrumPlot_, plain);
  shrinkInteraction_ = new PlotInteraction(shrinkPlot_, plain);

  // Room for the gap map's and the shrink plot's rows of labels (one a
  // line, never over each other): on a small window the view scrolls
  // vertically instead of squeezing them.
  shrinkPlot_->setMinimumHeight(240);
  for (QwtPlot* p : {curvePlot_, gapMapPlot_, spectrumPlot_, shrinkPlot_}) useCompactTitles(p);
  auto* grid = new QGridLayout();
  grid->addWidget(curvePlot_, 0, 0);
  grid->addWidget(gapMapPlot_, 0, 1);
  grid->addWidget(spectrumPlot_, 1, 0);
  grid->addWidget(shrinkPlot_, 1, 1);
  auto* plots = new QWidget();
  plots->setLayout(grid);
  return plots;
}

// The plots above the diagnosis' text, or the placeholder in their stead.
QStackedWidget* DiagnosisView::buildResultStack(QWidget* plots) {
  text_ = new QPlainTextEdit();
  text_->setObjectName("diagnosisText");
  text_->setReadOnly(true);
  text_->setLineWrapMode(QPlainTextEdit::NoWrap);
  QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  mono.setStyleHint(QFont::TypeWriter);
  text_->setFont(mono);
  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(plots);
  split->addWidget(text_);
  split->setStretchFactor(0, 4);
  split->setStretchFactor(1, 1);
  // The plots only with a result; before it, what is going on.
  placeholder_ = new QLabel();
  placeholder_->setObjectName("diagnosisPlaceholder");
  placeholder_->setAlignment(Qt::AlignCenter);
  placeholder_->setWordWrap(true);
  placeholder_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  QFont large = placeholder_->font();
  large.setPointSizeF(large.pointSizeF() * 1.25);
  placeholder_->setFont(large);
  placeholder_->setStyleSheet("color: #505050");
  stack_ = new QStackedWidget();
  stack_->addWidget(placeholder_);
  stack_->addWidget(split);
  return stack_;
}

QString DiagnosisView::verdictText() const { return verdict_->text(); }

QString DiagnosisView::stageShown() const { return stage_->text(); }
bool DiagnosisView::plotsShown() const { return stack_->currentIndex() == 1; }

QString DiagnosisView::stageText(const std::string& stage) {
  if (stage == "calibration") return tr("calibrating the replay to the session");
  if (stage == "replays") return tr("replaying the session in the simulator");
  if (stage == "gap map") return tr("mapping the gap");
  if (stage == "effects") return tr("fitting the candidate effects");
  if (stage == "refinement") return tr("refining the best effects");
  if (stage == "pairs") return tr("trying pairs of effects");
  if (stage == "verdict") return tr("reaching the verdict");
  return coreText(stage);
}

void DiagnosisView::setVerdict(const QString& text) {
  verdict_->setText(text);
  fitVerdictHeight();
}

// The scroll area around the view sizes it from its minimum size hint,
// which takes the wrapped verdict at its preferred width (fewer lines): at
// 1024x700 a 4-line verdict squeezed the plots 56 px below their minimum
// and each row of plots overlapped the next. Its height for its width now
// is its minimum.
void DiagnosisView::fitVerdictHeight() { verdict_->setMinimumHeight(verdict_->heightForWidth(verdict_->width())); }

// Every n-th segment named, n as small as the canvas allows with a gap
// between labels ("P1 S1 P1 S2" ran together on a 155-px canvas).
void DiagnosisView::fitGapMapColumns() {
  const int nCols = static_cast<int>(columnNames_.size());
  if (nCols == 0) return;
  const QFontMetrics metrics(gapMapPlot_->axisWidget(QwtPlot::xBottom)->font());
  int widest = 0;
  for (const QString& name : columnNames_) widest = std::max(widest, metrics.horizontalAdvance(name + QLatin1Char(' ')));
  const QwtInterval shown = gapMapPlot_->axisInterval(QwtPlot::xBottom);  // as zoomed
  const int width = std::max(1, gapMapPlot_->canvas()->width());
  const double step = std::max(1.0, std::ceil(shown.width() * widest / width));
  if (gapMapPlot_->axisStepSize(QwtPlot::xBottom) == step) return;
  gapMapPlot_->setAxisScale(QwtPlot::xBottom, shown.minValue(), shown.maxValue(), step);
  gapMapPlot_->replot();
}

void DiagnosisView::showPlaceholder(const QString& text) {
  placeholder_->setText(text);
  stack_->setCurrentIndex(0);
  {
    const QSignalBlocker block(pointCombo_);
    pointCombo_->clear();
  }
  // Test points only with a result.
  pointLabel_->hide();
  pointCombo_->hide();
}

void DiagnosisView::applyStatedNoise(diagnosis::DiagnosisOptions& options) const {
  if (!noiseStated_->isChecked()) return;
  options.biasInstabilityDegPerH = instability_->value();
  options.biasCorrelationS = correlation_->value();
}

void DiagnosisView::startDiagnosis(const QString& title) {
  state_ = State::kRunning;
  diagnosis_.reset();
  progress_->setValue(0);
  stage_->setText(tr("starting …"));
  cancel_->setEnabled(true);
  progressRow_->show();
  setVerdict(tr("<b>Diagnosing %1</b>: replaying it in the simulator and comparing.").arg(title.toHtmlEscaped()));
  text_->clear();
  showPlaceholder(tr("Diagnosing %1 …\nThe plots appear when the diagnosis is done.").arg(title));
}

void DiagnosisView::setProgress(double fraction, const std::string& stage) {
  if (state_ != State::kRunning) return;
  progress_->setValue(static_cast<int>(std::lround(1000.0 * std::clamp(fraction, 0.0, 1.0))));
  if (cancel_->isEnabled()) stage_->setText(stageText(stage));
}

void DiagnosisView::showCancelled(const QString& title) {
  state_ = State::kCancelled;
  diagnosis_.reset();
  progressRow_->hide();
  setVerdict(tr("<b>Diagnosis cancelled</b>: %1 has no diagnosis.").arg(title.toHtmlEscaped()));
  showPlaceholder(tr("Diagnosis cancelled.\nPress Diagnose in the Results view to start it again."));
}

void DiagnosisView::showMessage(const QString& message) {
  if (state_ == State::kRunning) state_ = State::kFailed;
  progressRow_->hide();
  setVerdict(message);
  if (!diagnosis_) showPlaceholder(message);
}

void DiagnosisView::showDiagnosis(std::shared_ptr<const diagnosis::Diagnosis> d, const QString& title) {
  diagnosis_ = std::move(d);
  if (!diagnosis_) return;
  state_ = State::kShown;
  progressRow_->hide();
  stack_->setCurrentIndex(1);
  pointLabel_->show();
  pointCombo_->show();
  QString gaps;
  for (std::size_t i = 0; i < diagnosis_->gapBefore.size() && i < diagnosis_->gapAfter.size(); ++i)
    gaps += tr("%1 %2 → %3   ")
                .arg(coreText(diagnosis::channelName(diagnosis_->gapBefore[i].channel)))
                .arg(localNumber(diagnosis_->gapBefore[i].rmsZ, 'f', 2))
                .arg(localNumber(diagnosis_->gapAfter[i].rmsZ, 'f', 2));
  setVerdict(tr("<b>%1 — verdict: %2</b><br>%3<br>gap per channel (rms z, 1 = within the simulator's "
                "spread), before → after: %4")
                 .arg(title.toHtmlEscaped(), coreText(diagnosis::effectTitle(diagnosis_->verdict)).toHtmlEscaped(),
                      coreText(diagnosis_->verdictReason).toHtmlEscaped(), gaps));
  // The identifier the JSON and the CLI's options use, for whoever needs it.
  verdict_->setToolTip(tr("verdict: %1 (the JSON's \"verdict\")").arg(QString::fromStdString(diagnosis_->verdict)));
  text_->setPlainText(coreText(diagnosis::formatDiagnosisText(*diagnosis_)));
  {
    const QSignalBlocker block(pointCombo_);
    pointCombo_->clear();
    for (const auto& p : diagnosis_->points)
      pointCombo_->addItem(tr("%1: %2 axis, %3 Hz").arg(p.point + 1).arg(axisLetter(static_cast<int>(p.axis)))
                               .arg(localNumber(p.frequencyHz, 'g', 4)));
  }
  showGapMap();
  showShrink();
  showPoint(0);
}

void DiagnosisView::showPoint(int position) {
  curvePlot_->detachItems(QwtPlotItem::Rtti_PlotCurve);
  spectrumPlot_->detachItems(QwtPlotItem::Rtti_PlotMultiBarChart);
  if (!diagnosis_ || position < 0 || position >= static_cast<int>(diagnosis_->points.size())) {
    curvePlot_->replot();
    spectrumPlot_->replot();
    return;
  }
  const auto& p = diagnosis_->points[static_cast<std::size_t>(position)];
  auto addCurve = [&](const diagnosis::PointSpectrum& s, const QString& name, const QColor& colour) {
    QVector<QPointF> points;
    for (std::size_t i = 0; i < s.residualTimeS.size() && i < s.gyroResidualDeg.size(); ++i)
      points.push_back({s.residualTimeS[i], s.gyroResidualDeg[i] * 3600.0});
    auto* c = new QwtPlotCurve(name);
    c->setPen(QPen(colour, 1.2));
    c->setSamples(points);
    c->attach(curvePlot_);
  };
  addCurve(p.real, tr("recorded"), kReal);
  addCurve(p.simulated, tr("simulated (replay)"), kSim);
  curvePlot_->setAxisAutoScale(QwtPlot::xBottom);
  curvePlot_->setAxisAutoScale(QwtPlot::yLeft);
  curvePlot_->replot();
  curveInteraction_->dataChanged();
  curveInteraction_->setHome();

  // Harmonics 2..5 of both channels, recorded beside simulated.
  auto* bars = new QwtPlotMultiBarChart();
  bars->setStyle(QwtPlotMultiBarChart::Grouped);
  const QList<QwtText> titles = {QwtText(tr("table, recorded")), QwtText(tr("table, simulated")),
                                 QwtText(tr("gyro, recorded")), QwtText(tr("gyro, simulated"))};
  bars->setBarTitles(titles);
  const QColor colours[] = {QColor(31, 119, 180), QColor(158, 202, 225), QColor(255, 127, 14), QColor(253, 208, 162)};
  for (int i = 0; i < 4; ++i) {
    auto* symbol = new QwtColumnSymbol(QwtColumnSymbol::Box);
    symbol->setPalette(QPalette(colours[i]));
    symbol->setLineWidth(0);
    bars->setSymbol(i, symbol);
  }
  QVector<QwtSetSample> samples;
  auto at = [](const std::vector<double>& v, int h) { return h < static_cast<int>(v.size()) ? v[static_cast<std::size_t>(h)] : 0.0; };
  for (int h = 2; h <= 5; ++h)
    samples.push_back(QwtSetSample(h, QVector<double>{at(p.real.tableHarmonicPpm, h), at(p.simulated.tableHarmonicPpm, h),
                                                      at(p.real.gyroHarmonicPpm, h), at(p.simulated.gyroHarmonicPpm, h)}));
  bars->setSamples(samples);
  bars->attach(spectrumPlot_);
  spectrumPlot_->setAxisScale(QwtPlot::xBottom, 1.5, 5.5, 1.0);
  spectrumPlot_->setAxisAutoScale(QwtPlot::yLeft);
  spectrumPlot_->replot();
  spectrumInteraction_->setHome();
}

void DiagnosisView::showGapMap() {
  rowNames_.clear();
  columnNames_.clear();
  std::map<std::pair<int, int>, int> columns;                 // (point, segment) -> column
  std::map<std::tuple<int, std::string, int>, int> rows;      // (channel, quantity, axis) -> row
  std::map<std::string, std::string> titles;                  // quantity name -> in words
  for (const auto& c : diagnosis_->gapMap) {
    columns.emplace(std::pair{c.key.point, c.key.segment}, 0);
    rows.emplace(std::tuple{static_cast<int>(c.key.channel), quantityName(c.key), c.key.axis}, 0);
    titles.emplace(quantityName(c.key), diagnosis::quantityTitle(c.key));
  }
  int i = 0;
  for (auto& [key, index] : columns) {
    index = i++;
    columnNames_ << tr("P%1 S%2").arg(key.first + 1).arg(key.second + 1);
  }
  i = 0;
  for (auto& [key, index] : rows) {
    index = i++;
    const auto& [channel, quantity, axis] = key;
    rowNames_ << QString("%1 %2 %3")
                     .arg(coreText(diagnosis::channelName(static_cast<diagnosis::Channel>(channel))),
                          coreText(titles[quantity]), axisLetter(axis))
                     .trimmed();
  }
  const int nRows = static_cast<int>(rowNames_.size()), nCols = static_cast<int>(columnNames_.size());
  QVector<double> values(nRows * nCols, 0.0);
  for (const auto& c : diagnosis_->gapMap) {
    const int r = rows[{static_cast<int>(c.key.channel), quantityName(c.key), c.key.axis}];
    const int col = columns[{c.key.point, c.key.segment}];
    values[r * nCols + col] = std::clamp(c.z, -kZRange, kZRange);
  }
  auto* raster = new QwtMatrixRasterData();
  raster->setValueMatrix(values, std::max(nCols, 1));
  raster->setInterval(Qt::XAxis, QwtInterval(-0.5, nCols - 0.5));
  raster->setInterval(Qt::YAxis, QwtInterval(-0.5, nRows - 0.5));
  raster->setInterval(Qt::ZAxis, QwtInterval(-kZRange, kZRange));
  raster->setResampleMode(QwtMatrixRasterData::NearestNeighbour);
  gapMap_->setData(raster);
  auto diverging = [] {
    auto* map = new QwtLinearColorMap(QColor(33, 102, 172), QColor(178, 24, 43));
    map->addColorStop(0.5, Qt::white);
    return map;
  };
  gapMap_->setColorMap(diverging());
  auto* bar = gapMapPlot_->axisWidget(QwtPlot::yRight);
  bar->setColorBarEnabled(true);
  bar->setColorMap(QwtInterval(-kZRange, kZRange), diverging());
  gapMapPlot_->enableAxis(QwtPlot::yRight);
  gapMapPlot_->setAxisScale(QwtPlot::yRight, -kZRange, kZRange);
  gapMapPlot_->setAxisTitle(QwtPlot::yRight, tr("z"));
  gapMapPlot_->setAxisScaleDraw(QwtPlot::xBottom, new NamedScaleDraw(columnNames_));
  gapMapPlot_->setAxisScaleDraw(QwtPlot::yLeft, new NamedScaleDraw(rowNames_));
  // Readable labels (at least 9 pt); with many rows every n-th is named
  // rather than all of them shrunk to a few pixels.
  const double kLabelsShown = 8.0;
  const double rowStep = std::max(1.0, std::ceil(nRows / kLabelsShown));
  gapMapPlot_->setAxisScale(QwtPlot::xBottom, -0.5, nCols - 0.5, std::max(1.0, std::ceil(nCols / kLabelsShown)));
  gapMapPlot_->setAxisScale(QwtPlot::yLeft, -0.5, nRows - 0.5, rowStep);
  gapMapPlot_->setAxisMaxMinor(QwtPlot::xBottom, 0);
  gapMapPlot_->setAxisMaxMinor(QwtPlot::yLeft, 0);
  for (int axis : {QwtPlot::yLeft, QwtPlot::xBottom}) {
    QFont font = gapMapPlot_->axisWidget(axis)->font();
    if (font.pointSizeF() < kMinLabelPt) font.setPointSizeF(kMinLabelPt);
    gapMapPlot_->axisWidget(axis)->setFont(font);
  }
  fitGapMapColumns();
  // "P1 S2" explained where it is read.
  QwtText columnsTitle(tr("P test point, S segment"));
  QFont titleFont = gapMapPlot_->axisWidget(QwtPlot::xBottom)->font();
  columnsTitle.setFont(titleFont);
  gapMapPlot_->setAxisTitle(QwtPlot::xBottom, columnsTitle);
  gapMapPlot_->replot();
  gapMapInteraction_->setHome();
}

void DiagnosisView::showShrink() {
  shrinkPlot_->detachItems(QwtPlotItem::Rtti_PlotBarChart);
  QStringList names;
  QVector<double> shrink;
  std::vector<bool> kept;
  // The best-ranked effects, as many as stay readable beside their bars at
  // a laptop's height (all of them are in the text below, ranked).
  constexpr std::size_t kShown = 6;
  const std::size_t count = std::min(kShown, diagnosis_->effects.size());
  for (std::size_t i = 0; i < count; ++i) {
    const auto& e = diagnosis_->effects[i];
    names << coreText(diagnosis::effectTitle(e.name));
    shrink << 100.0 * std::clamp(e.heldOutShrink, -1.0, 1.0);
    kept.push_back(e.kept);
  }
  auto* chart = new ShrinkChart(kept);
  chart->setOrientation(Qt::Horizontal);
  // Each bar 0.7 of its row, however many effects share the height.
  chart->setLayoutPolicy(QwtPlotAbstractBarChart::ScaleSamplesToAxes);
  chart->setLayoutHint(0.7);
  chart->setSamples(shrink);
  chart->attach(shrinkPlot_);
  // Ranked from the top: the scale runs from the last effect up to the first.
  shrinkPlot_->setAxisScaleDraw(QwtPlot::yLeft, new NamedScaleDraw(names));
  shrinkPlot_->setAxisScale(QwtPlot::yLeft, static_cast<double>(names.size()) - 0.4, -0.6, 1.0);
  shrinkPlot_->setAxisMaxMinor(QwtPlot::yLeft, 0);
  shrinkPlot_->setTitle(diagnosis_->effects.size() > count
                            ? tr("Held-out shrink: the %1 best-ranked of %2 effects (all in the text below)")
                                  .arg(count)
                                  .arg(diagnosis_->effects.size())
                            : tr("Held-out shrink per candidate effect"));
  const double lowest = shrink.isEmpty() ? 0.0 : *std::min_element(shrink.begin(), shrink.end());
  shrinkPlot_->setAxisScale(QwtPlot::xBottom, std::min(0.0, lowest), 100.0);
  shrinkPlot_->replot();
  shrinkInteraction_->setHome();
}

}  // namespace fog::ui
