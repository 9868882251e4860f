#include "engine/sun/sun_disc.hpp"

#include <tbb/parallel_for.h>

#include <vector>

#include "engine/envmap/latlong.hpp"

namespace lp {
namespace {

// f(x, angle) for each pixel of the span within `radius` of the axis.
template <class F>
void for_each_within(const RowSpan& s, int width, int height, const Direction& axis, double radius, F f) {
  for (int i = 0; i < s.count; ++i) {
    const int x = (s.x0 + i) % width;
    const double angle = angle_between(axis, pixel_centre_direction(x, s.y, width, height));
    if (angle <= radius) f(x, angle);
  }
}

void add(Power& sum, const float* rgb, double weight) {
  for (int c = 0; c < 3; ++c) sum[c] += double(rgb[c]) * weight;
}

}  // namespace

Power DiscSums::ring_mean() const {
  Power mean{};
  if (ring_solid_angle > 0)
    for (int c = 0; c < 3; ++c) mean[c] = ring[c] / ring_solid_angle;
  return mean;
}

DiscSums sum_disc_and_ring(const Image& image, const Direction& axis, double radius, double ring_radius) {
  const int w = image.width(), h = image.height();
  const auto spans = cone_row_spans(w, h, axis, ring_radius);
  std::vector<DiscSums> rows(spans.size());
  tbb::parallel_for(size_t(0), spans.size(), [&](size_t i) {
    const RowSpan& s = spans[i];
    const double omega = latlong::pixel_solid_angle(s.y, w, h);
    const float* row = image.row(s.y);
    DiscSums& r = rows[i];
    for_each_within(s, w, h, axis, ring_radius, [&](int x, double angle) {
      if (angle <= radius) {
        add(r.disc, row + 3 * x, omega);
        r.disc_solid_angle += omega;
        ++r.disc_pixels;
      } else {
        add(r.ring, row + 3 * x, omega);
        r.ring_solid_angle += omega;
      }
    });
  });
  DiscSums total;
  for (const DiscSums& r : rows) {
    for (int c = 0; c < 3; ++c) total.disc[c] += r.disc[c], total.ring[c] += r.ring[c];
    total.disc_solid_angle += r.disc_solid_angle;
    total.ring_solid_angle += r.ring_solid_angle;
    total.disc_pixels += r.disc_pixels;
  }
  return total;
}

void fill_disc(Image& image, const Direction& axis, double radius, const Power& fill) {
  const int w = image.width(), h = image.height();
  const auto spans = cone_row_spans(w, h, axis, radius);
  const Rgb value{float(fill[0]), float(fill[1]), float(fill[2])};
  tbb::parallel_for(size_t(0), spans.size(), [&](size_t i) {
    for_each_within(spans[i], w, h, axis, radius, [&](int x, double) { image.set(x, spans[i].y, value); });
  });
}

}  // namespace lp
