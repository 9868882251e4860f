#include "server/renders/render_pictures.hpp"

#include "engine/image/resize.hpp"

namespace lp::server {

api::RenderPictures pictures_of(const RenderImage& image, const render::RenderSettings& settings) {
  api::RenderPictures out;
  out.color = image.image.get();
  for (size_t p = 0; p < image.passes.size(); ++p) out.passes[p] = image.passes[p].get();
  out.transparent = settings.background.mode == render::BackgroundMode::Transparent;
  return out;
}

RenderImage fit_longest_side(const RenderImage& image, std::optional<int> longest) {
  RenderImage out{
      std::make_shared<const Image>(lp::fit_longest_side(*image.image, longest)), image.spp_done, {}};
  for (size_t p = 0; p < image.passes.size(); ++p)
    if (image.passes[p])
      out.passes[p] = std::make_shared<const Image>(lp::fit_longest_side(*image.passes[p], longest));
  return out;
}

}  // namespace lp::server
