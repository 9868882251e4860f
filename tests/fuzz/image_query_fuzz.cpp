// The query parameters of the image endpoints: samples.png, median-cut.png, sh and sh.png, brdf-lut, and the
// map and render images (format, exposure, gamma; projection, size and face, and the size they give), and
// thumbnails and a turntable's pictures (size, fps, an 8-bit format). One query goes to every parser.
// fuzz-dictionary: query.dict
#include "api/brdf_lut_request.hpp"
#include "api/median_cut_request.hpp"
#include "api/preview_params.hpp"
#include "api/projection_params.hpp"
#include "api/sample_request.hpp"
#include "api/sh_request.hpp"
#include "api/thumbnail_params.hpp"
#include "fuzz_input.hpp"

namespace {

template <typename Parse>
void parse(const Parse& parse_query) {
  try {
    parse_query();
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lp::api::Query q = lp::fuzz::as_query(lp::fuzz::as_text(data, size));
  const lp::api::RequestLimits limits;
  parse([&] { lp::api::parse_sample_image_query(q, limits); });
  parse([&] { lp::api::parse_median_cut_image_query(q, limits); });
  parse([&] { lp::api::parse_sh_query(q); });
  parse([&] { lp::api::parse_sh_image_query(q); });
  parse([&] { lp::api::parse_brdf_lut_query(q); });
  parse([&] { lp::api::parse_preview_params(q); });
  parse([&] {
    const lp::api::ProjectionParams p = lp::api::parse_projection_params(q);
    lp::api::projection_image_size(p, 1024, limits.max_pixels);
  });
  parse([&] { lp::api::parse_input_projection(q); });
  parse([&] { lp::api::parse_image_size(q); });
  parse([&] { lp::api::parse_animation_fps(q); });
  parse([&] { lp::api::parse_eight_bit_format(q); });
  parse([&] { lp::api::parse_turntable_tone(q); });
  return 0;
}
