// POST /api/v1/envmaps with a JSON body (load a map by its path in the data directory).
// fuzz-dictionary: json.dict
#include "api/envmap_load_request.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::api::parse_envmap_load_request(lp::fuzz::as_text(data, size));
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
