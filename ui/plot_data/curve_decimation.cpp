#include "ui/plot_data/curve_decimation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fog::ui {

QVector<QPointF> decimateMinMax(std::span<const double> x, std::span<const double> y, double x0, double x1,
                                int columns) {
  QVector<QPointF> out;
  const std::size_t n = std::min(x.size(), y.size());
  if (n == 0 || columns < 1 || !(x1 > x0)) return out;

  // [begin, end): the points in range plus one neighbour on each side.
  std::size_t begin = static_cast<std::size_t>(std::lower_bound(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), x0) - x.begin());
  std::size_t end = static_cast<std::size_t>(std::upper_bound(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), x1) - x.begin());
  if (begin > 0) --begin;
  if (end < n) ++end;
  if (begin >= end) return out;

  const auto cols = static_cast<std::size_t>(columns);
  if (end - begin <= 4 * cols) {
    out.reserve(static_cast<int>(end - begin));
    for (std::size_t i = begin; i < end; ++i) out.push_back(QPointF(x[i], y[i]));
    return out;
  }

  out.reserve(static_cast<int>(4 * cols + 2));
  const double perColumn = static_cast<double>(columns) / (x1 - x0);
  auto columnOf = [&](double xi) {
    const double c = std::floor((xi - x0) * perColumn);
    return static_cast<long>(std::clamp(c, -1.0, static_cast<double>(columns)));
  };

  std::size_t i = begin;
  while (i < end) {
    const long column = columnOf(x[i]);
    std::size_t first = i, last = i, lo = i, hi = i;
    for (++i; i < end && columnOf(x[i]) == column; ++i) {
      last = i;
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    std::array<std::size_t, 4> keep{first, lo, hi, last};
    std::sort(keep.begin(), keep.end());
    const auto unique = std::unique(keep.begin(), keep.end());
    for (auto k = keep.begin(); k != unique; ++k) out.push_back(QPointF(x[*k], y[*k]));
  }
  return out;
}

}  // namespace fog::ui
