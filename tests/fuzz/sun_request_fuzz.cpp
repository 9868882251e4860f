// POST /api/v1/envmaps/{id}/sun: the body (empty means every default).
// fuzz-dictionary: json.dict
#include "api/sun_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_sun_request(lp::fuzz::as_text(data, size));
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
