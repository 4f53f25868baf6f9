#include "ui/plan_editor.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/bench_presets.h"
#include "ui/core_text.h"
#include "ui/messages.h"

namespace fog::ui {

namespace {

// A spin box as wide as the value it shows, not as its range's widest
// ("-1000000.0 s"): the plan's columns fit their numbers, and the plan fits
// beside the rest of Configure on a laptop.
class ValueWideSpin : public QDoubleSpinBox {
 public:
  ValueWideSpin() {
    connect(this, &QDoubleSpinBox::textChanged, this, [this] { updateGeometry(); });
  }
  QSize sizeHint() const override {
    const QSize range = QDoubleSpinBox::sizeHint();
    if (buttonSymbols() != QAbstractSpinBox::NoButtons) return range;  // (Rest, beside the preset)
    return {std::min(range.width(), fontMetrics().horizontalAdvance(text()) + 14), range.height()};
  }
  QSize minimumSizeHint() const override { return sizeHint(); }
};

QDoubleSpinBox* makeSpin(double min, double max, int decimals, const QString& suffix) {
  auto* s = new ValueWideSpin();
  s->setRange(min, max);
  s->setDecimals(decimals);
  s->setSuffix(suffix);
  s->setKeyboardTracking(false);
  s->setFrame(false);
  s->setButtonSymbols(QAbstractSpinBox::NoButtons);
  s->setAlignment(Qt::AlignRight);
  return s;
}

QString durationText(double s) {
  return s >= 120 ? QObject::tr("%1 min").arg(s / 60.0, 0, 'f', 1) : QObject::tr("%1 s").arg(s, 0, 'f', 0);
}

}  // namespace

std::vector<PlanEditor::PointProblem> PlanEditor::pointProblems(const TestPoint& p, const TurntableLimits& limits) {
  using Field = TestPoint::Problem::Field;
  std::vector<PointProblem> out;
  for (const auto& problem : p.problems(limits)) {
    Column column = kCheck;
    switch (problem.field) {
      case Field::kPosition: column = kAxis; break;
      case Field::kKind: column = kKind; break;
      case Field::kFrequency: column = kFrequency; break;
      case Field::kAmplitude: column = kAmplitude; break;
      case Field::kDuration: column = kDuration; break;
      case Field::kSettle: column = kSettle; break;
      case Field::kStartPhase: column = kCheck; break;  // not a column of the table
    }
    out.push_back({column, coreText(problem.message)});
  }
  return out;
}

PlanEditor::PlanEditor(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);

  auto* top = new QHBoxLayout();
  top->addWidget(new QLabel(tr("Preset")));
  presetCombo_ = new QComboBox();
  presetCombo_->setObjectName("planPresetCombo");
  // Narrow on a laptop; the list shows the whole labels.
  presetCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  presetCombo_->setMinimumContentsLength(14);
  // The first entry stands for a plan that is no preset (edited, loaded
  // from a file): the box never names a preset the table does not hold.
  presetCombo_->addItem(tr("custom plan"), QString());
  for (const auto& p : benchPresets()) presetCombo_->addItem(p.displayLabel(), p.name);
  presetCombo_->setToolTip(tr("Choosing a preset replaces the plan below; an edited plan shows as \"custom plan\""));
  top->addWidget(presetCombo_, 1);
  top->addSpacing(12);
  top->addWidget(new QLabel(tr("Rest")));
  restSpin_ = makeSpin(0.0, 3600.0, 1, tr(" s"));
  restSpin_->setObjectName("restSpin");
  restSpin_->setFrame(true);
  restSpin_->setButtonSymbols(QAbstractSpinBox::UpDownArrows);
  restSpin_->setToolTip(tr("Rest between test points: the table at rest"));
  top->addWidget(restSpin_);
  layout->addLayout(top);

  table_ = new QTableWidget(0, kColumnCount);
  table_->setObjectName("planTable");
  table_->setHorizontalHeaderLabels({tr("Kind"), tr("Axis"), tr("Frequency"), tr("Amplitude"), tr("Duration"), tr("Periods"),
                                     tr("Settle"), tr("Check")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // The check is a short word (every problem is below the table), whole: a
  // table too narrow for it makes Configure give the plan more room.
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setWordWrap(false);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  layout->addWidget(table_, 1);

  auto* buttons = new QHBoxLayout();
  addButton_ = new QPushButton(tr("Add test point"));
  addButton_->setObjectName("addPointButton");
  removeButton_ = new QPushButton(tr("Remove"));
  removeButton_->setObjectName("removePointButton");
  upButton_ = new QPushButton(tr("Move up"));
  downButton_ = new QPushButton(tr("Move down"));
  for (auto* b : {addButton_, removeButton_, upButton_, downButton_}) buttons->addWidget(b);
  buttons->addStretch(1);
  summary_ = new QLabel();
  summary_->setObjectName("planSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addLayout(buttons);
  layout->addWidget(summary_);

  // A preset chosen applies at once; an edited plan it would replace is
  // kept unless the operator agrees.
  connect(presetCombo_, qOverload<int>(&QComboBox::activated), this, [this](int index) {
    const QString name = presetCombo_->itemData(index).toString();
    if (name.isEmpty() || name == shownPreset_) return;
    if (shownPreset_.isEmpty() && table_->rowCount() > 0 &&
        QMessageBox::question(this, tr("Replace the test plan?"),
                              tr("The plan below is not a preset (it was edited or loaded from a file). Replace it "
                                 "with the preset \"%1\"?")
                                  .arg(presetCombo_->itemText(index))) != QMessageBox::Yes) {
      showPresetOfPlan();
      return;
    }
    loadPreset(name);
  });
  connect(addButton_, &QPushButton::clicked, this, [this] {
    const int rows = table_->rowCount();
    addRow(rows > 0 ? rowPoint(rows - 1) : TestPoint{});
    table_->selectRow(rows);
    validate();
  });
  connect(removeButton_, &QPushButton::clicked, this, &PlanEditor::removeSelectedRow);
  connect(upButton_, &QPushButton::clicked, this, [this] { moveSelectedRow(-1); });
  connect(downButton_, &QPushButton::clicked, this, [this] { moveSelectedRow(+1); });
  connect(restSpin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &PlanEditor::validate);

  loadPreset(benchPresets().front().name);
}

QDoubleSpinBox* PlanEditor::spin(int row, Column column) const {
  return qobject_cast<QDoubleSpinBox*>(table_->cellWidget(row, column));
}

QWidget* PlanEditor::cellEditor(int row, Column column) const { return table_->cellWidget(row, column); }

void PlanEditor::addRow(const TestPoint& p) {
  const int row = table_->rowCount();
  table_->insertRow(row);
  auto* kind = new QComboBox();
  kind->addItem(tr("swing"));
  kind->addItem(tr("static"));
  kind->setToolTip(tr("static: the table at rest, to measure the gyro's noise (Allan deviation)"));
  kind->setCurrentIndex(p.isStatic() ? 1 : 0);
  kind->setFrame(false);
  table_->setCellWidget(row, kKind, kind);
  auto* axis = new QComboBox();
  axis->addItems({"X", "Y", "Z"});
  axis->setCurrentIndex(static_cast<int>(p.axis));
  axis->setFrame(false);
  // The table position and start phase have no column: a plan file's values
  // ride with the row so that editing it does not drop them.
  axis->setProperty("positionDeg", QVariantList{p.positionDeg[0], p.positionDeg[1], p.positionDeg[2]});
  axis->setProperty("startPhaseDeg", p.startPhaseDeg);
  if (p.positionDeg != std::array<double, kAxisCount>{})
    axis->setToolTip(tr("table position from the plan file: X %1°, Y %2°, Z %3°")
                         .arg(p.positionDeg[0]).arg(p.positionDeg[1]).arg(p.positionDeg[2]));
  table_->setCellWidget(row, kAxis, axis);
  // Wide ranges on purpose: the limits are the table's, checked and explained
  // by validate(), not silently clamped by the field.
  auto* f = makeSpin(0.0, 1000.0, 4, tr(" Hz"));
  auto* a = makeSpin(0.0, 360.0, 3, tr(" °"));
  auto* d = makeSpin(0.0, 1e6, 1, tr(" s"));
  auto* n = makeSpin(0.0, 1e7, 1, QString());
  auto* s = makeSpin(-1e6, 1e6, 1, tr(" s"));
  f->setValue(p.frequencyHz);
  a->setValue(p.amplitudeDeg);
  d->setValue(p.durationS);
  s->setValue(p.settleS);
  n->setValue(p.durationS * p.frequencyHz);
  f->setToolTip(tr("Swing frequency"));
  a->setToolTip(tr("Swing amplitude (peak)"));
  d->setToolTip(tr("Recorded time after settling; or give whole periods in the next column"));
  n->setToolTip(tr("Recorded swing periods (duration × frequency)"));
  s->setToolTip(tr("Swing time before recording starts"));
  table_->setCellWidget(row, kFrequency, f);
  table_->setCellWidget(row, kAmplitude, a);
  table_->setCellWidget(row, kDuration, d);
  table_->setCellWidget(row, kPeriods, n);
  table_->setCellWidget(row, kSettle, s);
  auto* check = new QTableWidgetItem();
  check->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
  table_->setItem(row, kCheck, check);

  // Rows move, so look the row up when an edit arrives.
  auto rowOf = [this](QWidget* w) {
    for (int r = 0; r < table_->rowCount(); ++r)
      for (int c = 0; c < kCheck; ++c)
        if (table_->cellWidget(r, c) == w) return r;
    return -1;
  };
  connect(axis, qOverload<int>(&QComboBox::currentIndexChanged), this, &PlanEditor::validate);
  connect(kind, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, kind, rowOf] {
    const int r = rowOf(kind);
    // A static segment has no swing: its fields would only mislead.
    for (Column c : {kFrequency, kAmplitude, kPeriods}) spin(r, c)->setEnabled(kind->currentIndex() == 0);
    if (kind->currentIndex() == 0 && !(spin(r, kFrequency)->value() > 0.0)) {
      spin(r, kFrequency)->setValue(1.0);
      spin(r, kAmplitude)->setValue(3.0);
    }
    validate();
  });
  for (Column c : {kFrequency, kAmplitude, kPeriods}) spin(row, c)->setEnabled(!p.isStatic());
  for (auto [w, col] : {std::pair{f, kFrequency}, {d, kDuration}, {n, kPeriods}, {a, kAmplitude}, {s, kSettle}})
    connect(w, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, w = w, col = col, rowOf] {
      syncPeriods(rowOf(w), col);
      validate();
    });
}

void PlanEditor::syncPeriods(int row, Column edited) {
  if (row < 0 || syncing_) return;
  syncing_ = true;
  const double f = spin(row, kFrequency)->value();
  if (edited == kPeriods && f > 0) spin(row, kDuration)->setValue(spin(row, kPeriods)->value() / f);
  else if (edited == kDuration || edited == kFrequency) spin(row, kPeriods)->setValue(spin(row, kDuration)->value() * f);
  syncing_ = false;
}

TestPoint PlanEditor::rowPoint(int row) const {
  TestPoint p;
  const auto* axisBox = qobject_cast<QComboBox*>(table_->cellWidget(row, kAxis));
  const QVariantList position = axisBox->property("positionDeg").toList();
  if (qobject_cast<QComboBox*>(table_->cellWidget(row, kKind))->currentIndex() == 1) {
    p = TestPoint::staticSegment(static_cast<Axis>(axisBox->currentIndex()), spin(row, kDuration)->value(),
                                 spin(row, kSettle)->value());
    for (int a = 0; a < kAxisCount && a < position.size(); ++a) p.positionDeg[a] = position[a].toDouble();
    return p;
  }
  for (int a = 0; a < kAxisCount && a < position.size(); ++a) p.positionDeg[a] = position[a].toDouble();
  p.startPhaseDeg = axisBox->property("startPhaseDeg").toDouble();
  p.axis = static_cast<Axis>(qobject_cast<QComboBox*>(table_->cellWidget(row, kAxis))->currentIndex());
  p.frequencyHz = spin(row, kFrequency)->value();
  p.amplitudeDeg = spin(row, kAmplitude)->value();
  p.durationS = spin(row, kDuration)->value();
  p.settleS = spin(row, kSettle)->value();
  return p;
}

TestPlan PlanEditor::plan() const {
  TestPlan plan;
  plan.restBetweenS = restSpin_->value();
  for (int r = 0; r < table_->rowCount(); ++r) plan.points.push_back(rowPoint(r));
  return plan;
}

void PlanEditor::setPlan(const TestPlan& plan) {
  {
    const QSignalBlocker block(restSpin_);
    restSpin_->setValue(plan.restBetweenS);
  }
  table_->setRowCount(0);
  for (const auto& p : plan.points) addRow(p);
  if (table_->rowCount() > 0) table_->selectRow(0);
  validate();
}

bool PlanEditor::loadPreset(const QString& name) {
  const auto preset = findBenchPreset(name);
  if (!preset) return false;
  setPlan(preset->plan);
  return true;
}

void PlanEditor::showPresetOfPlan() {
  const std::string now = testPlanToJson(plan());
  shownPreset_.clear();
  for (const auto& p : benchPresets())
    if (testPlanToJson(p.plan) == now) shownPreset_ = p.name;
  const QSignalBlocker block(presetCombo_);
  presetCombo_->setCurrentIndex(std::max(0, presetCombo_->findData(shownPreset_)));
}

void PlanEditor::setLimits(const table::TableLimits& limits) {
  limits_ = limits;
  validate();
}

void PlanEditor::setReadOnly(bool readOnly) {
  table_->setEnabled(!readOnly);
  for (auto* w : std::initializer_list<QWidget*>{presetCombo_, restSpin_, addButton_, removeButton_, upButton_,
                                                 downButton_})
    w->setEnabled(!readOnly);
}

void PlanEditor::removeSelectedRow() {
  const int row = table_->currentRow();
  if (row < 0) return;
  table_->removeRow(row);
  if (table_->rowCount() > 0) table_->selectRow(std::min(row, table_->rowCount() - 1));
  validate();
}

void PlanEditor::moveSelectedRow(int by) {
  const int row = table_->currentRow();
  const int to = row + by;
  if (row < 0 || to < 0 || to >= table_->rowCount()) return;
  TestPlan p = plan();
  std::swap(p.points[static_cast<std::size_t>(row)], p.points[static_cast<std::size_t>(to)]);
  setPlan(p);
  table_->selectRow(to);
}

void PlanEditor::validate() {
  QStringList problems;
  double totalS = restSpin_->value();
  for (int r = 0; r < table_->rowCount(); ++r) {
    const TestPoint p = rowPoint(r);
    const std::vector<PointProblem> found = pointProblems(p, limits_.axes[static_cast<std::size_t>(p.axis)]);
    const bool ok = found.empty();
    QStringList texts;
    for (const auto& f : found) texts << f.text;
    auto* check = table_->item(r, kCheck);
    // A word the column always has room for (a long text wrapped in it made
    // rows 100 px tall in a one-character column on a laptop); every
    // problem is whole in the tooltip and in the list below the table.
    const QString total = durationText(p.settleS + p.durationS);
    check->setText(ok ? tr("ok") : (found.size() == 1 ? tr("1 problem") : tr("%1 problems").arg(found.size())));
    check->setForeground(ok ? QColor(0, 110, 0) : QColor(190, 0, 0));
    check->setToolTip(ok ? (p.isStatic() ? tr("ok: table at rest, %1 in all").arg(total)
                                         : tr("ok: %1 periods, %2 in all").arg(p.durationS * p.frequencyHz, 0, 'f', 1)
                                               .arg(total))
                         : texts.join("\n"));
    // Mark each field a problem is about, its tooltip saying what.
    for (int c = kFrequency; c < kCheck; ++c) {  // the editable numbers
      QStringList about;
      for (const auto& f : found)
        if (f.column == c || (f.column == kDuration && c == kPeriods)) about << f.text;
      auto* s = spin(r, static_cast<Column>(c));
      s->setStyleSheet(about.isEmpty() ? QString() : QStringLiteral("background: #ffd6d6;"));
      s->setToolTip(about.join("\n"));
    }
    for (const QString& t : texts) problems << tr("test point %1: %2").arg(r + 1).arg(t);
    totalS += p.settleS + p.durationS + restSpin_->value();
  }
  if (table_->rowCount() == 0) problems << tr("the test plan has no test points: add one or load a preset");
  // Every problem, one a line, not only the first.
  const QString all = problems.join("\n");
  const bool changed = all != problem_;
  problem_ = all;
  summary_->setText(problem_.isEmpty()
                        ? tr("%1 test point(s), %2 in all").arg(table_->rowCount()).arg(durationText(totalS))
                        : tr("<span style='color:#b00000'>Cannot run: %1</span>")
                              .arg(problem_.toHtmlEscaped().replace("\n", "<br>")));
  removeButton_->setEnabled(table_->rowCount() > 0);
  showPresetOfPlan();
  emit planChanged();
  if (changed) emit validityChanged(problem_.isEmpty(), problem_);
}

}  // namespace fog::ui
