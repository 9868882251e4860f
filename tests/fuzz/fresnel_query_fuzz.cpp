// GET /api/v1/fresnel: the query ("eta_i=1&eta_t=1.45&step=5&format=csv"), parsed, and the table it
// asks for computed and written as JSON and CSV, as the server answers it.
// fuzz-dictionary: query.dict
#include "api/fresnel_request.hpp"
#include "api/fresnel_schema.hpp"
#include "engine/fresnel/fresnel_table.hpp"
#include "fuzz_input.hpp"

namespace {

template <typename Table, typename... Extra>
void write(const Table& table, const Extra&... extra) {
  lp::api::fresnel_json(table, extra...).dump();
  lp::api::fresnel_csv(table);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const lp::api::FresnelRequest r =
        lp::api::parse_fresnel_query(lp::fuzz::as_query(lp::fuzz::as_text(data, size)));
    if (r.conductor)
      write(lp::conductor_table(r.eta_i, r.conductor->eta, r.conductor->k, r.step), r.conductor->metal);
    else
      write(lp::dielectric_table(r.eta_i, r.eta_t, r.step));
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  return 0;
}
