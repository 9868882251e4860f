#include "engine/projection/grid_coverage.hpp"

#include <algorithm>
#include <cmath>

namespace lp {

void GridCoverage::measure(const PlanePolygon& polygon, const GridAxis& columns, const GridAxis& rows) {
  corners_.clear();
  int c1 = 0, r1 = 0;
  for (const Point2d& p : polygon) {
    const Corner corner{p, columns.cell(p.x), rows.cell(p.y)};
    if (corners_.empty()) c0_ = c1 = corner.column, r0_ = r1 = corner.row;
    c0_ = std::min(c0_, corner.column), c1 = std::max(c1, corner.column);
    r0_ = std::min(r0_, corner.row), r1 = std::max(r1, corner.row);
    corners_.push_back(corner);
  }
  columns_ = c1 - c0_ + 1, rows_ = r1 - r0_ + 1;
  const size_t cells = size_t(columns_) * size_t(rows_);
  partial_.assign(cells, 0.0);
  mark_.assign(cells, 0.0);
  for (size_t i = 0; i < corners_.size(); ++i)
    add_side(corners_[i], corners_[(i + 1) % corners_.size()], columns, rows);
}

// The side from a to b is walked cell by cell: at each grid line it crosses, the next cell is the
// neighbour across that line.
constexpr double kNever = 1e300;  // a fraction for a line the side does not cross

void GridCoverage::add_side(Corner a, Corner b, const GridAxis& columns, const GridAxis& rows) {
  if (a.at.y == b.at.y) return;  // no height: nothing to add
  const double dx = b.at.x - a.at.x, dy = b.at.y - a.at.y;
  const int step_c = b.column > a.column ? 1 : -1, step_r = b.row > a.row ? 1 : -1;
  int c = a.column, r = a.row;
  Point2d from = a.at;
  while (c != b.column || r != b.row) {
    // The fraction of the side at which it leaves the cell across a column line and across a row line.
    const double leave_c = c != b.column ? (columns.edge(c + (step_c > 0)) - a.at.x) / dx : kNever;
    const double leave_r = r != b.row ? (rows.edge(r + (step_r > 0)) - a.at.y) / dy : kNever;
    const double s = std::clamp(std::min(leave_c, leave_r), 0.0, 1.0);
    const Point2d to{a.at.x + s * dx, a.at.y + s * dy};
    add_stretch(from, to, c, r, columns);
    from = to;
    if (leave_c <= leave_r)
      c += step_c;
    else
      r += step_r;
  }
  add_stretch(from, b.at, c, r, columns);
}

// A straight stretch inside one cell: the integral over its height of the cell's width left of it.
void GridCoverage::add_stretch(Point2d a, Point2d b, int column, int row, const GridAxis& columns) {
  const size_t k = size_t(row - r0_) * size_t(columns_) + size_t(column - c0_);
  const double height = b.y - a.y;
  partial_[k] += ((a.x + b.x) / 2 - columns.edge(column)) * height;
  mark_[k] += height;
}

}  // namespace lp
