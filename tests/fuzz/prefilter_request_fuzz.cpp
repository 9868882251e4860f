// POST /api/v1/envmaps/{id}/prefilter: the body (empty means every default), and for a body accepted the
// status it is described by and the sizes of its files, which depend on its projection and format.
// fuzz-dictionary: json.dict
#include "api/prefilter_files.hpp"
#include "api/prefilter_request.hpp"
#include "api/prefilter_schema.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto request = lp::api::parse_prefilter_request(lp::fuzz::as_text(data, size));
    lp::api::Json status;
    lp::api::describe_prefilter(status, request, {"map", "/files", false, 0});
    for (const std::string& name : lp::api::prefilter_file_names(request))
      if (lp::api::prefilter_file_bytes(request, name) <= 0) __builtin_trap();
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
