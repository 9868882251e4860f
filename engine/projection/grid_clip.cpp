#include "engine/projection/grid_clip.hpp"

namespace lp {

GridAxis GridAxis::uniform(double start, double step, int cells, bool open) {
  GridAxis a;
  a.start_ = start, a.step_ = step, a.cells_ = cells, a.open_ = open;
  return a;
}

// A table's cells are found from uniform buckets, four per cell: the cell at a bucket's start, then
// forward along the edges (cells thinner than a bucket, as a lat-long map's rows at the poles, take a
// few steps).
GridAxis GridAxis::table(std::vector<double> edges) {
  GridAxis a;
  a.cells_ = int(edges.size()) - 1;
  a.edges_ = std::move(edges);
  const int buckets = 4 * a.cells_;
  a.start_ = a.edges_.front();
  a.step_ = (a.edges_.back() - a.edges_.front()) / buckets;
  int k = 0;
  for (int b = 0; b < buckets; ++b) {
    while (k + 1 < a.cells_ && a.edges_[size_t(k) + 1] <= a.start_ + b * a.step_) ++k;
    a.bucket_cell_.push_back(k);
  }
  return a;
}

int GridAxis::cell(double v) const {
  int k;
  if (edges_.empty()) {
    k = int(std::floor((v - start_) / step_));
    if (v < edge(k)) --k;  // the division can round across a line: agree with edge()
    if (v >= edge(k + 1)) ++k;
    if (open_) return k;
  } else {
    const int b = std::clamp(int((v - start_) / step_), 0, int(bucket_cell_.size()) - 1);
    k = bucket_cell_[size_t(b)];
    while (k > 0 && v < edges_[size_t(k)]) --k;  // a bucket's start rounded past v
    while (k + 1 < cells_ && v >= edges_[size_t(k) + 1]) ++k;
  }
  return std::clamp(k, 0, cells_ - 1);
}

void split_polygon(const PlanePolygon& in, int axis, double value, PlanePolygon& below, PlanePolygon& above) {
  below.clear();
  above.clear();
  const size_t n = in.size();
  for (size_t i = 0; i < n; ++i) {
    const Point2d a = in[i], b = in[(i + 1) % n];
    const double da = (axis == 0 ? a.x : a.y) - value, db = (axis == 0 ? b.x : b.y) - value;
    if (da <= 0) below.push_back(a);
    if (da >= 0) above.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const double t = da / (da - db);
      Point2d p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
      (axis == 0 ? p.x : p.y) = value;
      below.push_back(p);
      above.push_back(p);
    }
  }
}

// Relative to the first corner, which keeps the precision of small pieces far from the origin.
double polygon_area(const PlanePolygon& p) {
  double twice = 0;
  const Point2d o = p[0];
  for (size_t i = 2; i < p.size(); ++i) {
    const double ax = p[i - 1].x - o.x, ay = p[i - 1].y - o.y, bx = p[i].x - o.x, by = p[i].y - o.y;
    twice += ax * by - bx * ay;
  }
  return twice / 2;
}

}  // namespace lp
