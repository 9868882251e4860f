// A lat-long map as a resampling source. Its plane is (phi, t) with t = -z: a pixel is the rectangle
// [2 pi x / W, 2 pi (x+1) / W] x [-cos(pi y / H), -cos(pi (y+1) / H)], and area there is solid angle
// (Archimedes' cylinder). A polygon is unwrapped in phi (columns past either end wrap round); a corner at
// a pole becomes the stretch of the line t = -+1 between its neighbours' longitudes, and a polygon going
// round a pole is closed along that line.
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/projection/source_charts.hpp"

namespace lp {
namespace {

// Sides spanning more longitude than this are cut too, near the poles where a short side can turn far.
constexpr double kMaxSideLongitude = kPi / 180;

double wrap_angle(double a) {  // into (-pi, pi]
  return a - 2 * kPi * std::ceil((a - kPi) / (2 * kPi));
}

bool at_pole(Vec3d p) {
  return p.x * p.x + p.y * p.y <= 1e-24 * dot(p, p);
}

class LatLongSource final : public ProjectionSource {
 public:
  explicit LatLongSource(const Image& image)
      : image_(image),
        columns_(GridAxis::uniform(0, 2 * kPi / image.width(), image.width(), true)),
        rows_(GridAxis::table(row_edges(image.height()))) {}

  bool needs_split(Vec3d a, Vec3d b) const override {
    if (ProjectionSource::needs_split(a, b)) return true;
    if (at_pole(a) || at_pole(b)) return false;
    // cos(longitude between them) < cos(kMaxSideLongitude), squared to spare a root
    static const double cos_max = std::cos(kMaxSideLongitude);
    const double c = a.x * b.x + a.y * b.y;
    return c < 0 || c * c < cos_max * cos_max * (a.x * a.x + a.y * a.y) * (b.x * b.x + b.y * b.y);
  }

  void integrate(std::span<const Vec3d> polygon, SourceScratch& s, TexelSum& sum) const override {
    if (!unwrap(polygon, s.plane)) return;
    const int w = image_.width();
    s.coverage.cover(s.plane, columns_, rows_, [&](int c, int r, double area) {
      sum.add(image_.row(r) + 3 * (((c % w) + w) % w), area);
    });
  }

 private:
  static std::vector<double> row_edges(int height) {
    std::vector<double> t(size_t(height) + 1);
    for (int y = 0; y <= height; ++y) t[size_t(y)] = -std::cos(kPi * y / height);
    t.front() = -1, t.back() = 1;
    return t;
  }

  // The polygon in the (phi, t) plane; false if it has no area there.
  static bool unwrap(std::span<const Vec3d> polygon, PlanePolygon& out) {
    out.clear();
    const size_t n = polygon.size();
    size_t first = 0;
    while (first < n && at_pole(polygon[first])) ++first;
    if (first == n) return false;
    double phi = std::atan2(polygon[first].y, polygon[first].x), mean_z = 0;
    const double start_phi = phi;
    bool after_pole = false;
    for (size_t k = 0; k < n; ++k) {
      const Vec3d p = polygon[(first + k) % n];
      mean_z += p.z;
      if (at_pole(p)) {
        after_pole = true;
        continue;
      }
      const double next_phi = phi + wrap_angle(std::atan2(p.y, p.x) - phi);
      if (after_pole) {  // the pole's stretch, from the last longitude to this one
        const double pole_t = polygon[(first + k + n - 1) % n].z > 0 ? -1 : 1;
        out.push_back({phi, pole_t});
        out.push_back({next_phi, pole_t});
        after_pole = false;
      }
      phi = next_phi;
      out.push_back({phi, -p.z});
    }
    const double end_phi = phi + wrap_angle(start_phi - phi);
    if (after_pole) {
      const double pole_t = polygon[(first + n - 1) % n].z > 0 ? -1 : 1;
      out.push_back({phi, pole_t});
      out.push_back({end_phi, pole_t});
    } else if (std::abs(end_phi - start_phi) > kPi) {  // round a pole: close along its line
      const double pole_t = mean_z > 0 ? -1 : 1;
      out.push_back({end_phi, out.front().y});
      out.push_back({end_phi, pole_t});
      out.push_back({start_phi, pole_t});
    }
    return out.size() >= 3;
  }

  const Image& image_;
  GridAxis columns_, rows_;
};

}  // namespace

std::unique_ptr<const ProjectionSource> make_latlong_source(const Image& image) {
  return std::make_unique<LatLongSource>(image);
}

}  // namespace lp
