// POST /api/v1/renders: the body, parsed and validated into the renderer's scene, lighting and settings.
// fuzz-dictionary: json.dict
#include "api/render_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_render_request(lp::api::parse_json_object(lp::fuzz::as_text(data, size)),
                                  lp::api::RequestLimits{});
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
