#pragma once
// A small flowing page layout for the calibration report: blocks (headings,
// wrapped paragraphs, tables, plots) are placed top to bottom in millimetres
// on A4 pages and start a new page when they do not fit. Internal to
// fog_report.
//
// Pages are laid out twice with the same code: once measuring only (no
// painter), to learn the page count that every footer prints, then drawing.
// Both passes measure text on the same paint device, so they break pages at
// the same places.

#include <QColor>
#include <QFont>
#include <QPainter>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>
#include <memory>
#include <vector>

#include "core/common/status.h"

class QwtPlot;

namespace fog::report::detail {

// Where pages go. beginPage() returns the painter for the new page, or null
// when the pass only measures.
class PageTarget {
 public:
  virtual ~PageTarget() = default;
  virtual const QPaintDevice* metricsDevice() const = 0;
  virtual double dotsPerMm() const = 0;
  virtual QPainter* beginPage() = 0;
  virtual void endPage() = 0;
};

struct TableColumn {
  QString title;
  double widthMm = 20.0;
  Qt::Alignment align = Qt::AlignLeft;
};

struct Table {
  std::vector<TableColumn> columns;
  std::vector<QStringList> rows;  // one string per column
  std::vector<bool> boldRows;     // optional, by row
  double fontPt = 8.5;
};

class PageFlow {
 public:
  static constexpr double kPageWidthMm = 210.0, kPageHeightMm = 297.0;
  static constexpr double kLeftMm = 18.0, kRightMm = 18.0, kTopMm = 22.0, kBottomMm = 20.0;
  static constexpr double kContentWidthMm = kPageWidthMm - kLeftMm - kRightMm;
  static constexpr double kPlotGapMm = 4.0;  // below each plot

  // decorate(flow, page, pageCount) draws the header and footer of each page;
  // pageCount is 0 in the measuring pass. drawn collects drawn strings.
  using Decorate = std::function<void(PageFlow&, int page, int pageCount)>;
  PageFlow(PageTarget& target, int pageCount, Decorate decorate, QStringList* drawn);
  ~PageFlow();

  bool drawing() const { return painter_ != nullptr; }
  int page() const { return page_; }  // 1-based, 0 before the first
  double y() const { return y_; }     // cursor, mm from the page top
  double remainingMm() const { return kPageHeightMm - kBottomMm - y_; }

  void newPage();
  void finish();  // ends the last page
  // New page unless heightMm fits below the cursor.
  void ensureSpace(double heightMm);
  void space(double mm) { y_ += mm; }

  static QFont font(double pt, bool bold = false, bool mono = false);

  // Text in a rectangle (mm), wrapped at word boundaries when the flags say
  // Qt::TextWordWrap. Recorded in the drawn list.
  void text(const QRectF& mm, int flags, const QString& s, const QFont& f, const QColor& c = Qt::black);
  // `f`, or smaller so that the widest word of `cell` fits `widthMm`.
  QFont fitting(const QString& cell, const QFont& f, double widthMm) const;
  double textHeightMm(const QString& s, const QFont& f, double widthMm) const;
  double textWidthMm(const QString& s, const QFont& f) const;
  void line(double x0, double y0, double x1, double y1, const QColor& c = Qt::black, double widthMm = 0.2);
  void rect(const QRectF& mm, const QColor& border, const QColor& fill, double borderMm = 0.3);

  // Blocks at the cursor.
  void heading(const QString& s);
  void paragraph(const QString& s, const QFont& f, const QColor& c = Qt::black);
  // Rows split across pages, the header repeated on each.
  void table(const Table& t);
  // Label/value pairs in two columns (a borderless table).
  // Rows of a bold key and its value; the values of `monoRows` (hashes,
  // identifiers) in a monospace face.
  void keyValues(const std::vector<std::pair<QString, QString>>& rows, double keyWidthMm,
                 const std::vector<std::size_t>& monoRows = {});
  // A Qwt plot rendered into the full content width; make() is called only
  // when drawing, with the size of the plot in mm.
  void plot(double heightMm, const std::function<std::unique_ptr<QwtPlot>(double widthMm, double heightMm)>& make);

  QRectF px(const QRectF& mm) const;

 private:
  PageTarget& target_;
  QPainter* painter_ = nullptr;
  int page_ = 0, pageCount_ = 0;
  double y_ = 0.0;
  Decorate decorate_;
  QStringList* drawn_ = nullptr;
  bool inPage_ = false;
};

}  // namespace fog::report::detail
