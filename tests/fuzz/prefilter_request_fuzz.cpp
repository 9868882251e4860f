// POST /api/v1/envmaps/{id}/prefilter: the body (empty means every default).
// fuzz-dictionary: json.dict
#include "api/prefilter_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_prefilter_request(lp::fuzz::as_text(data, size));
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
