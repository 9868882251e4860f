#pragma once
// A render job's images as the API's pictures take them (api/render_pictures.hpp), and their thumbnails.
#include <optional>

#include "api/render_pictures.hpp"
#include "engine/render/scene_desc.hpp"
#include "server/renders/render_job_image.hpp"

namespace lp::server {

// Views of `image`'s colour and passes; `image` must outlive them.
api::RenderPictures pictures_of(const RenderImage& image, const render::RenderSettings& settings);

// The colour and every pass resampled so the longest side is `longest` (engine/image/resize.hpp).
RenderImage fit_longest_side(const RenderImage& image, std::optional<int> longest);

}  // namespace lp::server
