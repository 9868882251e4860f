#pragma once
// Cutting a plane polygon along the lines of a rectilinear grid: the pieces it leaves in each cell. This
// is how a texel of one projection is laid over the texels of another in a plane where the second's
// texels are rectangles.
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/projection/geometry.hpp"

namespace lp {

using PlanePolygon = std::vector<Point2d>;

// The cell boundaries along one axis: cell k spans [edge(k), edge(k + 1)]. Uniform (start + k step) or
// from a table of increasing values. An open axis numbers cells beyond its ends (the caller wraps them,
// as the longitude of a lat-long map); a closed one gives the first or last cell for values outside.
class GridAxis {
 public:
  static GridAxis uniform(double start, double step, int cells, bool open = false);
  static GridAxis table(std::vector<double> edges);

  int cell(double v) const;
  double edge(int k) const { return edges_.empty() ? start_ + k * step_ : edges_[size_t(k)]; }

 private:
  double start_ = 0, step_ = 1;
  int cells_ = 0;
  bool open_ = false;
  std::vector<double> edges_;
  std::vector<int> bucket_cell_;  // a table's cell at the start of each of its uniform buckets
};

// The part of `in` with coordinate `axis` (0: x, 1: y) below `value` into `below`, the rest into `above`.
void split_polygon(const PlanePolygon& in, int axis, double value, PlanePolygon& below, PlanePolygon& above);

double polygon_area(const PlanePolygon& p);  // signed: positive counter-clockwise (x right, y up)

// Reused buffers, one per thread.
struct GridClipScratch {
  PlanePolygon row_piece, row_rest, cell_piece, cell_rest, spare;
};

// Calls visit(k, piece) for the strips k = first .. last of `polygon` along `axis`: the last strip takes
// what is left. `piece`, `rest` and `spare` are buffers.
template <class Visit>
void for_each_strip(const PlanePolygon& polygon, int axis, const GridAxis& lines, int first, int last,
                    PlanePolygon& piece, PlanePolygon& rest, PlanePolygon& spare, Visit&& visit) {
  rest = polygon;
  for (int k = first; k <= last; ++k) {
    if (k < last) {
      split_polygon(rest, axis, lines.edge(k + 1), piece, spare);
      std::swap(rest, spare);
    } else {
      std::swap(piece, rest);
    }
    if (piece.size() >= 3) visit(k, piece);
  }
}

// Calls visit(column, row, piece) for the piece of `polygon` in every cell its bounding box meets (a piece
// may be of zero area).
template <class Visit>
void for_each_cell_piece(const PlanePolygon& polygon, const GridAxis& columns, const GridAxis& rows,
                         GridClipScratch& s, Visit&& visit) {
  double x0 = polygon[0].x, x1 = x0, y0 = polygon[0].y, y1 = y0;
  for (const Point2d& p : polygon) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const int r0 = rows.cell(y0), r1 = rows.cell(y1), c0 = columns.cell(x0), c1 = columns.cell(x1);
  if (r0 == r1 && c0 == c1) {
    visit(c0, r0, polygon);
    return;
  }
  for_each_strip(polygon, 1, rows, r0, r1, s.row_piece, s.row_rest, s.spare,
                 [&](int r, const PlanePolygon& strip) {
                   for_each_strip(strip, 0, columns, c0, c1, s.cell_piece, s.cell_rest, s.spare,
                                  [&](int c, const PlanePolygon& piece) { visit(c, r, piece); });
                 });
}

}  // namespace lp
