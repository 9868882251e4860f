#pragma once
// The pictures the tool writes of a finished render, encoded as the API's image endpoint encodes them
// (api/render_pictures.hpp): the colour in the format asked for (with its alpha when the background is
// transparent) and the passes the request keeps. An EXR holds every pass as its channels, as
// pass=all&format=exr gives it; another format writes the colour to OUT and each other pass to
// OUT's name with the pass's name before its extension (thumb.png: thumb.albedo.png, thumb.depth.png).
// The alpha of a transparent render is the colour's own alpha channel, not a file of its own.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "api/preview_params.hpp"
#include "api/render_pictures.hpp"
#include "engine/render/renderer.hpp"

namespace lp::cli {

// A finished render's colour and the passes its settings keep.
class RenderedImages {
 public:
  RenderedImages(const render::Renderer& renderer, const render::RenderSettings& settings);
  api::RenderPictures pictures() const;

 private:
  Image color_;
  std::array<std::optional<Image>, enum_entries(render::AuxPass{}).size()> passes_;
  bool transparent_;
};

// The colour (for EXR, with every pass as channels).
std::vector<uint8_t> encode_picture(const RenderedImages& images, const api::PreviewParams& params);

// The passes written as files of their own beside the colour in `format`.
std::vector<render::AuxPass> separate_passes(const render::RenderSettings& settings, ImageFormat format);
std::vector<uint8_t> encode_pass(const RenderedImages& images, render::AuxPass pass,
                                 const api::PreviewParams& params);
// OUT.EXT -> OUT.NAME.EXT.
std::filesystem::path pass_file(const std::filesystem::path& output, render::AuxPass pass);

// Refuses (bad_request) passes that would be files of their own with nowhere to go: on standard output or
// beside a turntable's frames.
void refuse_unwritten_passes(const render::RenderSettings& settings, ImageFormat format,
                             const std::optional<std::string>& file, bool turntable);

}  // namespace lp::cli
