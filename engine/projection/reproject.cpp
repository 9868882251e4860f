#include "engine/projection/reproject.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "engine/projection/projection_source.hpp"
#include "engine/projection/projection_texels.hpp"
#include "engine/projection/target_panels.hpp"

namespace lp {
namespace {

struct PanelRow {
  size_t panel;
  int j;
};

// One task's rows: the corner rows above and below the current row, carried from one row to the next.
class RowResampler {
 public:
  RowResampler(const Image& image, Projection from, const ProjectionSource& source, Image& out)
      : image_(image), from_(from), source_(source), out_(out) {}

  void run(const TargetPanel& panel, PanelRow row) {
    if (row.panel == panel_ && row.j == j_ + 1) {
      std::swap(top_, bottom_);
      panel.corner_row(row.j + 1, bottom_);
    } else {
      panel.corner_row(row.j, top_);
      panel.corner_row(row.j + 1, bottom_);
    }
    panel_ = row.panel, j_ = row.j;
    for (int i = 0; i < panel.width(); ++i) {
      const size_t k = size_t(i);
      panel.outline(i, row.j, {top_[k], bottom_[k], bottom_[k + 1], top_[k + 1]}, source_, outline_);
      TexelSum sum;
      source_.integrate(outline_, scratch_, sum);
      out_.set(panel.origin().x + i, panel.origin().y + row.j,
               sum.area != 0 ? mean(sum) : nearest(panel.direction({i + 0.5, row.j + 0.5})));
    }
  }

 private:
  // Rounding can leave a cell a texel does not cover an area of about 1e-17 of its own, of either sign:
  // next to radiance some 1e17 times brighter, a black texel could come out below zero.
  static Rgb mean(const TexelSum& sum) {
    const auto channel = [&](double v) { return float(std::max(0.0, v / sum.area)); };
    return {channel(sum.r), channel(sum.g), channel(sum.b)};
  }
  // For a texel too small to cut: the source texel at its centre.
  Rgb nearest(Vec3d centre) const {
    const Pixel p = texel_containing(from_, {image_.width(), image_.height()}, centre);
    return image_.at(p.x, p.y);
  }

  const Image& image_;
  Projection from_;
  const ProjectionSource& source_;
  Image& out_;
  size_t panel_ = size_t(-1);
  int j_ = -1;
  std::vector<Vec3d> top_, bottom_;
  SphericalPolygon outline_;
  SourceScratch scratch_;
};

}  // namespace

Image reproject(const Image& image, Projection from, Projection to, int size) {
  const auto source = make_projection_source(image, from);
  const std::vector<TargetPanel> panels = TargetPanel::of(to, size);
  std::vector<PanelRow> rows;
  for (size_t p = 0; p < panels.size(); ++p)
    for (int j = 0; j < panels[p].height(); ++j) rows.push_back({p, j});
  const ImageShape shape = projection_shape(to, size);
  Image out(shape.width, shape.height);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rows.size()), [&](const tbb::blocked_range<size_t>& range) {
    RowResampler resampler(image, from, *source, out);
    for (size_t r = range.begin(); r != range.end(); ++r) resampler.run(panels[rows[r].panel], rows[r]);
  });
  return out;
}

}  // namespace lp
