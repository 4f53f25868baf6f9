#include "ui/report/page_flow.h"

#include <QFontMetricsF>
#include <QRegularExpression>
#include <algorithm>
#include <qwt_plot.h>
#include <qwt_plot_renderer.h>

namespace fog::report::detail {

namespace {

constexpr double kCellPadMm = 1.2;
constexpr int kWrap = Qt::TextWordWrap;

}  // namespace

PageFlow::PageFlow(PageTarget& target, int pageCount, Decorate decorate, QStringList* drawn)
    : target_(target), pageCount_(pageCount), decorate_(std::move(decorate)), drawn_(drawn) {}

PageFlow::~PageFlow() = default;

QFont PageFlow::font(double pt, bool bold, bool mono) {
  // DejaVu ships with Debian's Qt; the style hint picks a fallback elsewhere.
  QFont f(mono ? "DejaVu Sans Mono" : "DejaVu Sans");
  f.setStyleHint(mono ? QFont::TypeWriter : QFont::SansSerif);
  f.setPointSizeF(pt);
  f.setBold(bold);
  // No ligatures: text copied from the PDF must be the text drawn (an "ff"
  // ligature made a copied SHA-256 unverifiable). The report's scripts,
  // Latin and Chinese, need no shaping.
  f.setStyleStrategy(QFont::PreferNoShaping);
  return f;
}

QRectF PageFlow::px(const QRectF& mm) const {
  const double k = target_.dotsPerMm();
  return {mm.x() * k, mm.y() * k, mm.width() * k, mm.height() * k};
}

void PageFlow::newPage() {
  if (inPage_) target_.endPage();
  painter_ = target_.beginPage();
  inPage_ = true;
  ++page_;
  y_ = kTopMm;
  if (decorate_) decorate_(*this, page_, pageCount_);
}

void PageFlow::finish() {
  if (inPage_) target_.endPage();
  inPage_ = false;
  painter_ = nullptr;
}

void PageFlow::ensureSpace(double heightMm) {
  if (!inPage_ || heightMm > remainingMm()) newPage();
}

void PageFlow::text(const QRectF& mm, int flags, const QString& s, const QFont& f, const QColor& c) {
  if (!painter_ || s.isEmpty()) return;
  painter_->setFont(f);
  painter_->setPen(c);
  painter_->drawText(px(mm), flags, s);
  if (drawn_) drawn_->append(s);
}

double PageFlow::textHeightMm(const QString& s, const QFont& f, double widthMm) const {
  const QFontMetricsF fm(f, const_cast<QPaintDevice*>(target_.metricsDevice()));
  const double k = target_.dotsPerMm();
  if (s.isEmpty()) return fm.height() / k;
  return fm.boundingRect(QRectF(0, 0, widthMm * k, 1e7), kWrap, s).height() / k;
}

double PageFlow::textWidthMm(const QString& s, const QFont& f) const {
  const QFontMetricsF fm(f, const_cast<QPaintDevice*>(target_.metricsDevice()));
  return fm.horizontalAdvance(s) / target_.dotsPerMm();
}

void PageFlow::line(double x0, double y0, double x1, double y1, const QColor& c, double widthMm) {
  if (!painter_) return;
  const double k = target_.dotsPerMm();
  painter_->setPen(QPen(c, widthMm * k));
  painter_->drawLine(QPointF(x0 * k, y0 * k), QPointF(x1 * k, y1 * k));
}

void PageFlow::rect(const QRectF& mm, const QColor& border, const QColor& fill, double borderMm) {
  if (!painter_) return;
  painter_->setPen(QPen(border, borderMm * target_.dotsPerMm()));
  painter_->setBrush(fill);
  painter_->drawRect(px(mm));
  painter_->setBrush(Qt::NoBrush);
}

void PageFlow::heading(const QString& s) {
  const QFont f = font(12.0, true);
  const double h = textHeightMm(s, f, kContentWidthMm);
  ensureSpace(h + 2.0 + 15.0);  // never alone at the bottom of a page
  y_ += 2.0;
  text(QRectF(kLeftMm, y_, kContentWidthMm, h), Qt::AlignLeft | kWrap, s, f, QColor(20, 40, 90));
  y_ += h + 0.8;
  line(kLeftMm, y_, kLeftMm + kContentWidthMm, y_, QColor(20, 40, 90), 0.3);
  y_ += 2.0;
}

void PageFlow::paragraph(const QString& s, const QFont& f, const QColor& c) {
  const double h = textHeightMm(s, f, kContentWidthMm);
  ensureSpace(h);
  text(QRectF(kLeftMm, y_, kContentWidthMm, h), Qt::AlignLeft | kWrap, s, f, c);
  y_ += h + 1.5;
}

QFont PageFlow::fitting(const QString& cell, const QFont& f, double widthMm) const {
  // Every digit stays on the page: a word (a number, a hash) wider than its
  // column is set smaller until it fits, never cut at the column's edge.
  double widest = 0.0;
  for (const QString& word : cell.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts))
    widest = std::max(widest, textWidthMm(word, f));
  if (widest <= widthMm || widest <= 0.0) return f;
  QFont smaller = f;
  smaller.setPointSizeF(std::max(4.0, f.pointSizeF() * widthMm / widest * 0.98));
  return smaller;
}

void PageFlow::table(const Table& t) {
  const QFont normal = font(t.fontPt), bold = font(t.fontPt, true);
  auto cellFont = [&](const QStringList& cells, int i, const QFont& f) {
    return fitting(cells[i], f, t.columns[static_cast<std::size_t>(i)].widthMm - 2 * kCellPadMm);
  };
  auto rowHeight = [&](const QStringList& cells, const QFont& f) {
    double h = 0.0;
    for (int i = 0; i < static_cast<int>(t.columns.size()) && i < cells.size(); ++i)
      h = std::max(h, textHeightMm(cells[i], cellFont(cells, i, f),
                                   t.columns[static_cast<std::size_t>(i)].widthMm - 2 * kCellPadMm));
    return h + 2 * kCellPadMm * 0.6;
  };
  auto drawRow = [&](const QStringList& cells, const QFont& f, double h, bool header) {
    double x = kLeftMm;
    double total = 0.0;
    for (const auto& c : t.columns) total += c.widthMm;
    if (header) rect(QRectF(kLeftMm, y_, total, h), QColor(225, 230, 240), QColor(225, 230, 240), 0.1);
    for (int i = 0; i < static_cast<int>(t.columns.size()) && i < cells.size(); ++i) {
      const auto& col = t.columns[static_cast<std::size_t>(i)];
      text(QRectF(x + kCellPadMm, y_ + kCellPadMm * 0.6, col.widthMm - 2 * kCellPadMm, h),
           static_cast<int>(col.align | Qt::AlignTop) | kWrap, cells[i], cellFont(cells, i, f));
      x += col.widthMm;
    }
    y_ += h;
    line(kLeftMm, y_, kLeftMm + total, y_, header ? QColor(90, 90, 90) : QColor(200, 200, 200), header ? 0.25 : 0.12);
  };
  QStringList titles;
  for (const auto& c : t.columns) titles << c.title;
  const bool hasHeader = std::any_of(titles.begin(), titles.end(), [](const QString& s) { return !s.isEmpty(); });
  const double headerH = hasHeader ? rowHeight(titles, bold) : 0.0;
  bool needHeader = true;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const bool isBold = r < t.boldRows.size() && t.boldRows[r];
    const double h = rowHeight(t.rows[r], isBold ? bold : normal);
    if (h + (needHeader ? headerH : 0.0) > remainingMm()) {
      newPage();
      needHeader = true;
    }
    if (needHeader && hasHeader) drawRow(titles, bold, headerH, true);
    needHeader = false;
    drawRow(t.rows[r], isBold ? bold : normal, h, false);
  }
  y_ += 2.5;
}

void PageFlow::keyValues(const std::vector<std::pair<QString, QString>>& rows, double keyWidthMm,
                         const std::vector<std::size_t>& monoRows) {
  const QFont key = font(9.0, true), plain = font(9.0), mono = font(8.5, false, true);
  const double valueWidth = kContentWidthMm - keyWidthMm;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& [k, v] = rows[i];
    const QFont& value = std::find(monoRows.begin(), monoRows.end(), i) != monoRows.end() ? mono : plain;
    const double h = std::max(textHeightMm(k, key, keyWidthMm - 2.0), textHeightMm(v, value, valueWidth)) + 0.9;
    ensureSpace(h);
    text(QRectF(kLeftMm, y_, keyWidthMm - 2.0, h), Qt::AlignLeft | kWrap, k, key, QColor(60, 60, 60));
    text(QRectF(kLeftMm + keyWidthMm, y_, valueWidth, h), Qt::AlignLeft | kWrap, v, value);
    y_ += h;
  }
  y_ += 2.0;
}

void PageFlow::plot(double heightMm,
                    const std::function<std::unique_ptr<QwtPlot>(double widthMm, double heightMm)>& make) {
  ensureSpace(heightMm);
  if (painter_) {
    auto p = make(kContentWidthMm, heightMm);
    // The renderer lays the plot out in the widget's own coordinates and
    // scales them to the page, so the widget needs a size of the same shape.
    const double widgetPxPerMm = p->logicalDpiX() / 25.4;
    p->resize(static_cast<int>(kContentWidthMm * widgetPxPerMm), static_cast<int>(heightMm * widgetPxPerMm));
    p->replot();
    QwtPlotRenderer renderer;
    renderer.setDiscardFlag(QwtPlotRenderer::DiscardBackground, true);
    renderer.setDiscardFlag(QwtPlotRenderer::DiscardCanvasBackground, false);
    renderer.setDiscardFlag(QwtPlotRenderer::DiscardCanvasFrame, true);
    painter_->save();
    renderer.render(p.get(), painter_, px(QRectF(kLeftMm, y_, kContentWidthMm, heightMm)));
    painter_->restore();
  }
  y_ += heightMm + kPlotGapMm;
}

}  // namespace fog::report::detail
