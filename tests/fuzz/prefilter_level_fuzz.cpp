// GET /api/v1/prefilters/{id}/levels/{n}.png: the level `n` of a chain of 1 to 11 levels (the first byte
// chooses how many), any other text a 404.
#include "api/prefilter_files.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  lp::api::PrefilterRequest request;
  request.params.levels = 1 + data[0] % 11;
  try {
    const int level = lp::api::prefilter_level_index(request, lp::fuzz::as_text(data + 1, size - 1));
    if (level < 0 || level >= request.params.levels) std::abort();
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
