#pragma once
// POST /envmaps/{id}/median-cut body and GET /envmaps/{id}/median-cut.png query.
#include <cstdint>

#include "api/parameters.hpp"
#include "api/params.hpp"
#include "engine/image/image_io.hpp"
#include "engine/mediancut/median_cut.hpp"
#include "engine/mediancut/median_cut_plot.hpp"

namespace lp::api {

// {"count":64,"placement":"centroid","split":"median","luminance":"average"}, every field optional
// (defaults shown); count an integer in [1, max_lights]. An empty body means all defaults.
MedianCutParams parse_median_cut_request(const std::string& body, const RequestLimits& limits);

struct MedianCutImageRequest {
  MedianCutParams params;
  MedianCutStyle style = MedianCutStyle::Regions;
  ToneMap tone;
};

// count, placement, split, luminance (as the body), style=regions|lights, exposure, gamma.
MedianCutImageRequest parse_median_cut_image_query(const Query& q, const RequestLimits& limits);

// 400 naming `count` if the map has fewer pixels than lights asked for.
void check_count_fits(const MedianCutParams& params, int64_t pixel_count);

}  // namespace lp::api
