// POST /api/v1/turntables: the body, a render request and its turntable, parsed and validated.
// fuzz-dictionary: json.dict
#include "api/turntable_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_turntable_request(lp::api::parse_json_object(lp::fuzz::as_text(data, size)),
                                     lp::api::RequestLimits{});
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
