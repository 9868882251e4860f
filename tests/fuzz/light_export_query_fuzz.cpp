// POST /api/v1/envmaps/{id}/median-cut and .../sun: the query ("format=mitsuba&frame=world"), parsed,
// and a small set of lights written in the format it names, as the server answers it.
// fuzz-dictionary: query.dict
#include "api/api_error.hpp"
#include "api/light_export.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const lp::api::LightExportQuery q =
        lp::api::parse_light_export_query(lp::fuzz::as_query(lp::fuzz::as_text(data, size)));
    if (q.format == lp::api::LightFormat::Answer) return 0;
    lp::api::LightSet set{"fuzz", {{"sun", {0, 0.6, 0.8}, {3, 2, 1}, 0.01}, {"below", {0, 0, -1}, {}, 0}}, 1};
    lp::api::export_lights(set, q.format, q.frame);
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
