#include "server/renders/render_pictures.hpp"

#include "engine/image/resize.hpp"

namespace lp::server {

api::RenderPictures pictures_of(const RenderImage& image, const render::RenderSettings& settings) {
  api::RenderPictures out;
  out.color = image.image.get();
  for (size_t p = 0; p < image.passes.size(); ++p) out.passes[p] = image.passes[p].get();
  out.denoised = image.denoised.get();
  out.transparent = settings.background.mode == render::BackgroundMode::Transparent;
  return out;
}

RenderImage fit_longest_side(const RenderImage& image, std::optional<int> longest) {
  const auto fit = [&](const Image& i) {
    return std::make_shared<const Image>(lp::fit_longest_side(i, longest));
  };
  RenderImage out{fit(*image.image),
                  image.spp_done,
                  {},
                  image.denoised ? fit(*image.denoised) : nullptr,
                  image.denoise_s};
  for (size_t p = 0; p < image.passes.size(); ++p)
    if (image.passes[p]) out.passes[p] = fit(*image.passes[p]);
  return out;
}

}  // namespace lp::server
