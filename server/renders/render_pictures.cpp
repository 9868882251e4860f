#include "server/renders/render_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "api/api_error.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/resize.hpp"

namespace lp::server {
namespace {

using render::AuxPass;

bool transparent(const render::RenderSettings& s) {
  return s.background.mode == render::BackgroundMode::Transparent;
}

const Image& pass_image(const RenderImage& image, AuxPass p) {
  const Image* pass = image.pass(p);
  if (!pass)
    throw api::ApiError(
        api::ErrorCode::PassNotRendered,
        fmt::format("the render did not ask for the '{}' pass; its request's \"passes\" names those it keeps",
                    enum_name(p)));
  return *pass;
}

// Each value of `image` through f, for an 8-bit picture of values in [0, 1].
template <class F>
Image mapped(const Image& image, F&& f) {
  Image out(image.width(), image.height());
  const auto in = image.data();
  auto o = out.data();
  for (size_t i = 0; i < in.size(); ++i) o[i] = f(in[i]);
  return out;
}

Image depth_greys(const Image& depth) {
  float near = std::numeric_limits<float>::infinity(), far = 0;
  for (const float d : depth.data())
    if (std::isfinite(d)) near = std::min(near, d), far = std::max(far, d);
  const float span = far > near ? far - near : 1.0f;
  return mapped(depth, [&](float d) { return std::isfinite(d) ? 1.0f - 0.9f * (d - near) / span : 0.0f; });
}

std::vector<uint8_t> aux_png(const Image& pass, AuxPass p, const ToneMap& tone) {
  const ToneMap linear{0, 1.0f, ToneCurve::Standard};
  switch (p) {
    case AuxPass::Albedo:
      return write_png(pass, tone);
    case AuxPass::Normal:
      return write_png(mapped(pass, [](float n) { return 0.5f * (n + 1); }), linear);
    case AuxPass::Depth:
      return write_png(depth_greys(pass), linear);
    case AuxPass::Alpha:
      return write_png(pass, linear);
  }
  return {};
}

// The colour (or `color` in its place: the denoised one) with the alpha of a transparent background.
std::vector<uint8_t> color_picture(const RenderImage& image, const Image& color,
                                   const api::PreviewParams& params, const render::RenderSettings& s) {
  if (!transparent(s)) return write_image(color, params.format, params.tone);
  const Image& alpha = pass_image(image, AuxPass::Alpha);
  if (params.format == ImageFormat::Png)
    return encode_png_rgba8(tone_map_rgba8(color, alpha, params.tone), color.width(), color.height());
  if (params.format == ImageFormat::Exr) return write_exr_rgba(color, alpha);
  return write_image(color, params.format, params.tone);
}

std::vector<uint8_t> all_passes(const RenderImage& image, const render::RenderSettings& s) {
  const Image& color = *image.image;
  const float* c = color.data().data();
  std::vector<ExrChannel> channels{{"R", c, 3}, {"G", c + 1, 3}, {"B", c + 2, 3}};
  const auto add = [&](AuxPass p, const char* layer, std::initializer_list<const char*> names) {
    const Image* pass = image.pass(p);
    if (!pass) return;
    int k = 0;
    for (const char* name : names)
      channels.push_back({std::string(layer) + name, pass->data().data() + k++, 3});
  };
  add(AuxPass::Alpha, transparent(s) ? "" : "Alpha.", {"A"});
  add(AuxPass::Albedo, "Albedo.", {"R", "G", "B"});
  add(AuxPass::Normal, "Ns.", {"X", "Y", "Z"});
  add(AuxPass::Depth, "Depth.", {"Z"});
  if (image.denoised) {
    const float* d = image.denoised->data().data();
    channels.insert(channels.end(),
                    {{"Denoised.R", d, 3}, {"Denoised.G", d + 1, 3}, {"Denoised.B", d + 2, 3}});
  }
  return write_exr_channels(color.width(), color.height(), channels);
}

}  // namespace

std::vector<uint8_t> encode_render_picture(const RenderImage& image, const api::RenderImagePass& pass,
                                           const api::PreviewParams& params,
                                           const render::RenderSettings& settings) {
  if (pass.all) {
    if (params.format != ImageFormat::Exr)
      throw api::invalid_field(
          "format", fmt::format("pass={} is one EXR of every pass: ask for format=exr", api::kAllPassesName));
    return all_passes(image, settings);
  }
  if (pass.denoised) {
    if (!image.denoised) throw std::logic_error("no denoised image to encode");
    return color_picture(image, *image.denoised, params, settings);
  }
  if (!pass.aux) return color_picture(image, *image.image, params, settings);
  const Image& aux = pass_image(image, *pass.aux);
  if (params.format == ImageFormat::Png) return aux_png(aux, *pass.aux, params.tone);
  return write_image(aux, params.format, params.tone);
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

int64_t render_picture_bytes(const api::RenderImagePass& pass, const api::PreviewParams& params,
                             const render::RenderSettings& s) {
  const int64_t one = encode_bytes(params.format, s.width, s.height);
  if (pass.all) return one * int64_t(2 + s.passes.list().size());
  // An RGBA picture: its alpha's channel beside the colour; a mapped pass: its copy in [0, 1].
  return 2 * one + EnvMap::image_bytes(s.width, s.height);
}

}  // namespace lp::server
