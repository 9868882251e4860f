// POST /api/v1/envmaps/{id}/median-cut: the body (empty means every default).
// fuzz-dictionary: json.dict
#include "api/median_cut_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_median_cut_request(lp::fuzz::as_text(data, size), lp::api::RequestLimits{});
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
