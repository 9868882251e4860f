#include "cli/render_picture.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/render_request.hpp"

namespace lp::cli {

RenderedImages::RenderedImages(const render::Renderer& renderer, const render::RenderSettings& settings)
    : color_(renderer.image()),
      transparent_(settings.background.mode == render::BackgroundMode::Transparent) {
  for (const render::AuxPass p : settings.passes.list()) passes_[size_t(p)] = renderer.image(p);
}

api::RenderPictures RenderedImages::pictures() const {
  api::RenderPictures out;
  out.color = &color_;
  for (size_t p = 0; p < passes_.size(); ++p) out.passes[p] = passes_[p] ? &*passes_[p] : nullptr;
  out.transparent = transparent_;
  return out;
}

std::vector<uint8_t> encode_picture(const RenderedImages& images, const api::PreviewParams& params) {
  const api::RenderImagePass pass{params.format == ImageFormat::Exr, std::nullopt};
  return api::encode_render_picture(images.pictures(), pass, params);
}

std::vector<render::AuxPass> separate_passes(const render::RenderSettings& settings, ImageFormat format) {
  std::vector<render::AuxPass> out;
  if (format == ImageFormat::Exr) return out;
  for (const render::AuxPass p : settings.passes.list())
    if (p != render::AuxPass::Alpha || settings.background.mode != render::BackgroundMode::Transparent)
      out.push_back(p);
  return out;
}

std::vector<uint8_t> encode_pass(const RenderedImages& images, render::AuxPass pass,
                                 const api::PreviewParams& params) {
  return api::encode_render_picture(images.pictures(), {false, pass}, params);
}

std::filesystem::path pass_file(const std::filesystem::path& output, render::AuxPass pass) {
  std::filesystem::path out = output;
  out.replace_filename(output.stem().string() + "." + std::string(enum_name(pass)) +
                       output.extension().string());
  return out;
}

void refuse_unwritten_passes(const render::RenderSettings& settings, ImageFormat format,
                             const std::optional<std::string>& file, bool turntable) {
  const auto separate = separate_passes(settings, format);
  if (separate.empty()) return;
  const bool to_stdout = !file || *file == "-";
  if (!turntable && !to_stdout) return;
  throw api::ApiError(
      api::ErrorCode::BadRequest,
      fmt::format("the '{}' pass is written as a file of its own beside -o FILE unless the output is EXR: "
                  "{}; ask for format exr, or leave the pass out of \"{}\"",
                  enum_name(separate.front()),
                  turntable ? "a turntable writes no passes beside its frames" : "give -o FILE",
                  api::kPassesField));
}

}  // namespace lp::cli
