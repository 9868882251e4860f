#pragma once
// The picture the tool writes of a finished render: its colour in the format asked for; for a transparent
// background, with its alpha as the API's image endpoint gives it: PNG RGBA (straight alpha), EXR RGBA
// (premultiplied), the other formats the premultiplied RGB.
#include <cstdint>
#include <vector>

#include "api/preview_params.hpp"
#include "api/render_request.hpp"
#include "engine/render/renderer.hpp"

namespace lp::cli {

// `color` is the renderer's colour, or that colour denoised.
std::vector<uint8_t> encode_picture(const Image& color, const render::Renderer& renderer,
                                    const render::RenderSettings& settings, const api::PreviewParams& params);

// Refuses (bad_request) a render whose request asks for passes the tool does not write: all but the alpha
// of a transparent background, and the albedo and normal a denoise takes.
void refuse_unwritten_passes(const api::RenderRequest& request);

}  // namespace lp::cli
