#pragma once
// A finished render's pictures, as GET /api/v1/renders/{id}/image answers them and `lightprobe render`
// writes them: the colour, one auxiliary pass, or every pass as the channels of one EXR.
//
// The colour of a transparent render is premultiplied by its alpha: EXR gives it as RGBA, PNG and WebP as
// RGBA with straight alpha, JPEG (no alpha) as that RGBA picture shown over white, as a page of a white
// background shows the PNG; PFM and HDR give the premultiplied RGB (over black). The auxiliary passes are
// linear values in EXR, PFM and HDR (alpha and depth as greys, depth +inf where no camera ray hit). As 8-bit
// pictures: albedo tone mapped like the colour, alpha as linear greys, normals as (n + 1) / 2 in linear bytes
// and depth as greys from white (nearest) to black (farthest, or no hit).
//
// Every pass in one EXR names its channels as pbrt-v4's GBufferFilm where it has the pass and as Cycles'
// passes where it does not: R, G, B (colour) and A (alpha, when the background is transparent; else
// Alpha.A, a coverage over an opaque colour), Albedo.R/G/B, Ns.X/Y/Z (the shading normal), Depth.Z.
#include <array>
#include <cstdint>
#include <vector>

#include "api/preview_params.hpp"
#include "api/render_image_pass.hpp"
#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::api {

// The images of a render: its colour and the means of the auxiliary passes it kept (null for the others).
struct RenderPictures {
  const Image* color = nullptr;
  std::array<const Image*, enum_entries(render::AuxPass{}).size()> passes{};
  bool transparent = false;  // the background: the colour is premultiplied by the alpha pass

  const Image* pass(render::AuxPass p) const { return passes[size_t(p)]; }
};

// Throws ApiError 409 pass_not_rendered for a pass the render did not keep, and 400 invalid_field for
// pass=all in another format than EXR.
std::vector<uint8_t> encode_render_picture(const RenderPictures& pictures, const RenderImagePass& pass,
                                           const PreviewParams& params);

// The memory encode_render_picture takes beyond the images, for a render of `passes` at width x height.
int64_t render_picture_bytes(const RenderImagePass& pass, const PreviewParams& params, int width, int height,
                             size_t passes);

}  // namespace lp::api
