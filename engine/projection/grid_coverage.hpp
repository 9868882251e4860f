#pragma once
// The exact area a plane polygon covers of each cell of a rectilinear grid, from its sides alone: each
// side adds, in every cell it passes through, the integral over its height there of the cell's width to
// the left of it, and marks that the cells further left in the row are covered over that height. With the
// sides' signed heights, what the sides on the right of a polygon add, those on its left take away again;
// a scan from right to left along each row then gives every cell its area. Signed: positive for a polygon
// turning counter-clockwise (x right, y up). Cheaper than cutting the polygon into pieces (grid_clip.hpp)
// when only the areas are needed.
#include <vector>

#include "engine/projection/grid_clip.hpp"

namespace lp {

class GridCoverage {
 public:
  // Calls visit(column, row, area) for every cell of the polygon's bounding box it covers.
  template <class Visit>
  void cover(const PlanePolygon& polygon, const GridAxis& columns, const GridAxis& rows, Visit&& visit) {
    measure(polygon, columns, rows);
    for (int r = 0; r < rows_; ++r) {
      double covered_height = 0;  // of the cells to the right
      for (int c = columns_ - 1; c >= 0; --c) {
        const size_t k = size_t(r) * size_t(columns_) + size_t(c);
        const double width = columns.edge(c0_ + c + 1) - columns.edge(c0_ + c);
        const double area = partial_[k] + width * covered_height;
        covered_height += mark_[k];
        if (area != 0) visit(c0_ + c, r0_ + r, area);
      }
    }
  }

 private:
  struct Corner {
    Point2d at;
    int column, row;  // its cell
  };
  void measure(const PlanePolygon& polygon, const GridAxis& columns, const GridAxis& rows);
  void add_side(Corner a, Corner b, const GridAxis& columns, const GridAxis& rows);
  void add_stretch(Point2d a, Point2d b, int column, int row, const GridAxis& columns);

  int c0_ = 0, r0_ = 0, columns_ = 0, rows_ = 0;  // the bounding box's cells
  std::vector<double> partial_, mark_;            // per cell of the box, row by row
  std::vector<Corner> corners_;
};

}  // namespace lp
