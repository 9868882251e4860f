// lightprobe fresnel: Fresnel reflectance tables, as GET /api/v1/fresnel answers them (JSON or CSV).
#include <fmt/format.h>

#include "api/fresnel_request.hpp"
#include "api/fresnel_schema.hpp"
#include "api/query_policy.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/output.hpp"
#include "engine/core/limits.hpp"
#include "engine/fresnel/fresnel_table.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "fresnel (--eta-t N | --metal NAME | --eta N --k N) [options]";

std::string table(const api::FresnelRequest& r) {
  if (r.conductor) {
    const auto t = conductor_table(r.eta_i, r.conductor->eta, r.conductor->k, r.step);
    return r.csv ? api::fresnel_csv(t) : api::fresnel_json(t, r.conductor->metal).dump() + "\n";
  }
  const auto t = dielectric_table(r.eta_i, r.eta_t, r.step);
  return r.csv ? api::fresnel_csv(t) : api::fresnel_json(t).dump() + "\n";
}

std::string help() {
  const api::FresnelRequest d = api::parse_fresnel_query({{"eta_t", "1"}});
  const auto index = fmt::format("in [{}, {}]", limits::kFresnelIndex.min, limits::kFresnelIndex.max);
  return "Fresnel reflectance from 0 to 90 degrees of incidence, of a dielectric pair or of a conductor "
         "seen\n"
         "from a medium: the answer of GET /api/v1/fresnel. The dielectric table has the Brewster and\n"
         "(from the denser side) the critical angle, and Schlick's approximation beside the exact "
         "values.\n\n" +
         option_line("--eta-i N",
                     fmt::format("index of the incident medium, {} (default {})", index, d.eta_i)) +
         option_line("--eta-t N", "index of the other medium, " + index + ": a dielectric table") +
         option_line("--metal NAME", "a conductor: " + api::join(metal_names(), ", ")) +
         option_line("--eta N, --k N",
                     fmt::format("or a conductor's index and extinction (k in [{}, {}])",
                                 limits::kFresnelExtinction.min, limits::kFresnelExtinction.max)) +
         option_line("--step DEG",
                     fmt::format("angle step in degrees, in [{}, {}] (default {})",
                                 limits::kFresnelStepDeg.min, limits::kFresnelStepDeg.max, d.step)) +
         option_line("--format NAME", choices(api::TableFormat::JsonDocument)) + output_help();
}

void run(Arguments& args) {
  args.expect_positional(0, kSynopsis);
  const auto file = args.take("output");
  const api::Query query = args.take_rest_as_query();
  api::QueryPolicy("GET", "/api/v1/fresnel").check(query);
  const std::string text = table(api::parse_fresnel_query(query));
  Output out(file);
  out.write(text);
  out.finish();
}

}  // namespace

Command fresnel_command() {
  return {"fresnel", kSynopsis, "Fresnel reflectance tables of dielectrics and conductors (JSON or CSV)",
          {},        help,      run};
}

}  // namespace lp::cli
