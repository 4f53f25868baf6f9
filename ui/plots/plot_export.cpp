#include "ui/plots/plot_export.h"

#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>
#include <qwt_plot.h>
#include <qwt_plot_renderer.h>

namespace fog::ui {

QString plotExportFilter() { return QObject::tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"); }

Status exportPlot(QwtPlot* plot, const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  QwtPlotRenderer renderer;
  renderer.setDiscardFlag(QwtPlotRenderer::DiscardBackground, false);
  if (suffix == "png") {
    QImage image(plot->size() * 2, QImage::Format_ARGB32);
    image.fill(Qt::white);
    image.setDotsPerMeterX(2 * 3780);
    image.setDotsPerMeterY(2 * 3780);
    {
      QPainter painter(&image);
      renderer.render(plot, &painter, QRectF(QPointF(0, 0), QSizeF(image.size())));
    }
    if (!image.save(path, "PNG")) return ioError("cannot write '" + path.toStdString() + "'");
    return Status::ok();
  }
  if (suffix != "svg" && suffix != "pdf")
    return invalidArgument("'" + path.toStdString() + "': choose a .png, .svg or .pdf file name");
  // renderDocument reports nothing; check that the file can be created first.
  QFile probe(path);
  if (!probe.open(QIODevice::WriteOnly)) return ioError("cannot write '" + path.toStdString() + "'");
  probe.close();
  renderer.renderDocument(plot, path, suffix, QSizeF(160, 100), 150);
  if (QFileInfo(path).size() == 0) return ioError("nothing was written to '" + path.toStdString() + "'");
  return Status::ok();
}

Status exportPlots(const std::vector<QwtPlot*>& plots, const QString& path) {
  if (plots.empty()) return invalidArgument("there is no plot to export");
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix != "png" && suffix != "svg" && suffix != "pdf")
    return invalidArgument("'" + path.toStdString() + "': choose a .png, .svg or .pdf file name");
  QwtPlotRenderer renderer;
  renderer.setDiscardFlag(QwtPlotRenderer::DiscardBackground, false);
  const int n = static_cast<int>(plots.size());
  // Draws every plot into its share of `page`, top to bottom.
  auto draw = [&](QPainter& painter, const QRectF& page) {
    const double h = page.height() / n;
    for (int i = 0; i < n; ++i)
      renderer.render(plots[static_cast<std::size_t>(i)], &painter,
                      QRectF(page.left(), page.top() + i * h, page.width(), h));
  };
  if (suffix == "png") {
    QImage image(1600, 640 * n, QImage::Format_ARGB32);
    image.fill(Qt::white);
    image.setDotsPerMeterX(2 * 3780);
    image.setDotsPerMeterY(2 * 3780);
    {
      QPainter painter(&image);
      draw(painter, QRectF(QPointF(0, 0), QSizeF(image.size())));
    }
    if (!image.save(path, "PNG")) return ioError("cannot write '" + path.toStdString() + "'");
    return Status::ok();
  }
  // The painters report nothing; check that the file can be created first.
  QFile probe(path);
  if (!probe.open(QIODevice::WriteOnly)) return ioError("cannot write '" + path.toStdString() + "'");
  probe.close();
  constexpr double kMmPerInch = 25.4, kWidthMm = 160.0, kPlotHeightMm = 80.0;
  bool painted = false;
  if (suffix == "svg") {
    constexpr int kDpi = 96;
    const QSize size(qRound(kWidthMm / kMmPerInch * kDpi), qRound(n * kPlotHeightMm / kMmPerInch * kDpi));
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setResolution(kDpi);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(QStringLiteral("fogbench plot"));
    QPainter painter;
    if (painter.begin(&svg)) {
      draw(painter, QRectF(QPointF(0, 0), QSizeF(size)));
      painted = painter.end();
    }
  } else {
    QPdfWriter pdf(path);
    pdf.setResolution(150);
    pdf.setPageSize(QPageSize(QSizeF(kWidthMm, n * kPlotHeightMm), QPageSize::Millimeter));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    pdf.setCreator(QStringLiteral("fogbench"));
    pdf.setTitle(QStringLiteral("fogbench plot"));
    QPainter painter;
    if (painter.begin(&pdf)) {
      draw(painter, QRectF(0, 0, pdf.width(), pdf.height()));
      painted = painter.end();
    }
  }
  if (!painted || QFileInfo(path).size() == 0) return ioError("nothing was written to '" + path.toStdString() + "'");
  return Status::ok();
}

}  // namespace fog::ui
