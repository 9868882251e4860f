#pragma once
// A render's pictures as GET /api/v1/renders/{id}/image answers them: the colour, one auxiliary pass,
// or every pass as the channels of one EXR.
//
// The colour of a transparent render is premultiplied by its alpha: EXR gives it as RGBA, PNG as RGBA
// with straight alpha; the other formats give the premultiplied RGB. The auxiliary passes are linear
// values in EXR, PFM and HDR (alpha and depth as greys, depth +inf where no camera ray hit). As PNG:
// albedo tone mapped like the colour, alpha as linear greys, normals as (n + 1) / 2 in linear bytes and
// depth as greys from white (nearest) to black (farthest, or no hit).
//
// pass=all (EXR only) names its channels as pbrt-v4's GBufferFilm where it has the pass and as Cycles'
// passes where it does not: R, G, B (colour) and A (alpha, when the background is transparent; else
// Alpha.A, a coverage over an opaque colour), Albedo.R/G/B, Ns.X/Y/Z (the shading normal), Depth.Z, and
// Denoised.R/G/B once a render with `denoise` has its denoised colour.
//
// pass=denoised is that colour, encoded as the colour is (with its alpha on a transparent background).
#include <cstdint>
#include <optional>
#include <vector>

#include "api/preview_params.hpp"
#include "api/render_image_pass.hpp"
#include "engine/render/scene_desc.hpp"
#include "server/renders/render_job_image.hpp"

namespace lp::server {

// Throws api::ApiError 409 pass_not_rendered for a pass the render's settings do not ask for, and 400
// invalid_field for pass=all in another format than EXR. pass=denoised needs image.denoised (the route
// answers its absence).
std::vector<uint8_t> encode_render_picture(const RenderImage& image, const api::RenderImagePass& pass,
                                           const api::PreviewParams& params,
                                           const render::RenderSettings& settings);

// The colour and every pass resampled so the longest side is `longest` (engine/image/resize.hpp).
RenderImage fit_longest_side(const RenderImage& image, std::optional<int> longest);

// The memory encode_render_picture takes beyond the images.
int64_t render_picture_bytes(const api::RenderImagePass& pass, const api::PreviewParams& params,
                             const render::RenderSettings& settings);

}  // namespace lp::server
