#pragma once
// POST /envmaps/{id}/samples body and GET /envmaps/{id}/samples.png query.
#include <cstdint>

#include "api/parameters.hpp"
#include "api/params.hpp"
#include "engine/envmap/luminance.hpp"
#include "engine/image/image_io.hpp"
#include "engine/envmap/sample_set.hpp"

namespace lp::api {

struct SampleRequest {
  SampleSetSpec spec;
  LuminanceMode luminance = LuminanceMode::Average;
};

SampleRequest parse_sample_request(const Json& body, const RequestLimits& limits);

enum class SampleImageStyle { Marks, Windows };
constexpr auto enum_entries(SampleImageStyle) {
  return std::to_array<EnumEntry<SampleImageStyle>>(
      {{SampleImageStyle::Marks, "marks"}, {SampleImageStyle::Windows, "windows"}});
}

struct SampleImageRequest {
  SampleRequest samples;
  SampleImageStyle style = SampleImageStyle::Marks;
  ToneMap tone;
};

SampleImageRequest parse_sample_image_query(const Query& q, const RequestLimits& limits);

// One binary sample record: 13 little-endian float32 values, in this order.
inline constexpr const char* kSampleRecordLayout =
    "pixel_x,pixel_y,u,v,dir_x,dir_y,dir_z,theta,phi,pdf,radiance_r,radiance_g,radiance_b";
inline constexpr int kSampleRecordFloats = 13;

}  // namespace lp::api
