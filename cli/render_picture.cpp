#include "cli/render_picture.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "engine/image/image_io.hpp"

namespace lp::cli {
namespace {

bool transparent(const render::RenderSettings& s) {
  return s.background.mode == render::BackgroundMode::Transparent;
}

}  // namespace

std::vector<uint8_t> encode_picture(const Image& color, const render::Renderer& renderer,
                                    const render::RenderSettings& settings,
                                    const api::PreviewParams& params) {
  if (!transparent(settings) || (params.format != ImageFormat::Png && params.format != ImageFormat::Exr))
    return write_image(color, params.format, params.tone);
  const Image alpha = renderer.image(render::AuxPass::Alpha);
  if (params.format == ImageFormat::Exr) return write_exr_rgba(color, alpha);
  return encode_png_rgba8(tone_map_rgba8(color, alpha, params.tone), color.width(), color.height());
}

void refuse_unwritten_passes(const api::RenderRequest& request) {
  const render::RenderSettings& settings = request.settings;
  const auto written = [&](render::AuxPass pass) {
    if (pass == render::AuxPass::Alpha) return transparent(settings);
    return request.denoise && (pass == render::AuxPass::Albedo || pass == render::AuxPass::Normal);
  };
  for (const render::AuxPass pass : settings.passes.list())
    if (!written(pass))
      throw api::ApiError(api::ErrorCode::BadRequest,
                          fmt::format("the tool writes a render's colour (and its alpha when the background "
                                      "is transparent), not its '{}' pass: ask the server for passes "
                                      "(GET /api/v1/renders/{{id}}/image?pass=NAME)",
                                      enum_name(pass)));
}

}  // namespace lp::cli
