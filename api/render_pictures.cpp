#include "api/render_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "api/api_error.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/encode_pixels8.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {
namespace {

using render::AuxPass;

const Image& pass_image(const RenderPictures& pictures, AuxPass p) {
  const Image* pass = pictures.pass(p);
  if (!pass)
    throw ApiError(
        ErrorCode::PassNotRendered,
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

std::vector<uint8_t> aux_picture8(const Image& pass, AuxPass p, const PreviewParams& params) {
  const ToneMap linear{0, 1.0f, ToneCurve::Standard};
  switch (p) {
    case AuxPass::Albedo:
      return write_image(pass, params.format, params.tone);
    case AuxPass::Normal:
      return write_image(mapped(pass, [](float n) { return 0.5f * (n + 1); }), params.format, linear);
    case AuxPass::Depth:
      return write_image(depth_greys(pass), params.format, linear);
    case AuxPass::Alpha:
      return write_image(pass, params.format, linear);
  }
  return {};
}

std::vector<uint8_t> transparent_color(const Image& color, const Image& alpha, const PreviewParams& params) {
  if (params.format == ImageFormat::Exr) return write_exr_rgba(color, alpha);
  if (!is_eight_bit(params.format)) return write_image(color, params.format, params.tone);
  const std::vector<uint8_t> rgba = tone_map_rgba8(color, alpha, params.tone);
  return encode_pixels8({rgba, color.width(), color.height(), 4}, params.format);
}

std::vector<uint8_t> all_passes(const RenderPictures& pictures) {
  const Image& color = *pictures.color;
  const float* c = color.data().data();
  std::vector<ExrChannel> channels{{"R", c, 3}, {"G", c + 1, 3}, {"B", c + 2, 3}};
  const auto add = [&](AuxPass p, const char* layer, std::initializer_list<const char*> names) {
    const Image* pass = pictures.pass(p);
    if (!pass) return;
    int k = 0;
    for (const char* name : names)
      channels.push_back({std::string(layer) + name, pass->data().data() + k++, 3});
  };
  add(AuxPass::Alpha, pictures.transparent ? "" : "Alpha.", {"A"});
  add(AuxPass::Albedo, "Albedo.", {"R", "G", "B"});
  add(AuxPass::Normal, "Ns.", {"X", "Y", "Z"});
  add(AuxPass::Depth, "Depth.", {"Z"});
  return write_exr_channels(color.width(), color.height(), channels);
}

}  // namespace

std::vector<uint8_t> encode_render_picture(const RenderPictures& pictures, const RenderImagePass& pass,
                                           const PreviewParams& params) {
  if (pass.all) {
    if (params.format != ImageFormat::Exr)
      throw invalid_field(
          "format", fmt::format("pass={} is one EXR of every pass: ask for format=exr", kAllPassesName));
    return all_passes(pictures);
  }
  if (!pass.aux) {
    if (!pictures.transparent) return write_image(*pictures.color, params.format, params.tone);
    return transparent_color(*pictures.color, pass_image(pictures, AuxPass::Alpha), params);
  }
  const Image& aux = pass_image(pictures, *pass.aux);
  if (is_eight_bit(params.format)) return aux_picture8(aux, *pass.aux, params);
  return write_image(aux, params.format, params.tone);
}

int64_t render_picture_bytes(const RenderImagePass& pass, const PreviewParams& params, int width, int height,
                             size_t passes) {
  const int64_t one = encode_bytes(params.format, width, height);
  if (pass.all) return one * int64_t(1 + passes);
  // An RGBA picture: its alpha's channel beside the colour (and its RGB over white); a mapped pass: its
  // copy in [0, 1].
  return 3 * one + EnvMap::image_bytes(width, height);
}

}  // namespace lp::api
