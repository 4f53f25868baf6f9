#include "ui/plots/plot_export.h"

#include <QFileInfo>
#include <QImage>
#include <QPainter>
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

}  // namespace fog::ui
