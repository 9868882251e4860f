// lightprobe sh MAP: the map's spherical harmonics, as GET /api/v1/envmaps/{id}/sh answers them.
#include <fmt/format.h>

#include <chrono>

#include "api/query_policy.hpp"
#include "api/sh_request.hpp"
#include "api/sh_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "sh MAP [options]";

std::string help() {
  return "The map projected onto real orthonormal spherical harmonics (z up, no Condon-Shortley phase;\n"
         "the answer states the conventions), with the irradiance of Ramamoorthi and Hanrahan with and\n"
         "without 1/pi: the answer of GET /api/v1/envmaps/{id}/sh, as JSON.\n\n" +
         option_line("--bands N", fmt::format("bands, in [{}, {}] (default {})", limits::kShBands.min,
                                              limits::kShBands.max, api::kDefaultShBands)) +
         option_line("--irradiance BOOL", "add the irradiance and Lambertian coefficients (default true)") +
         option_line("--window NAME", choices(ShWindow::None) + ": a ringing window over the bands") +
         invalid_pixel_policy_help() + output_help();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const auto file = args.take("output");
  const api::Query query = args.take_rest_as_query();
  api::QueryPolicy("GET", "/api/v1/envmaps/{id}/sh").check(query);
  const api::ShRequest request = api::parse_sh_query(query);
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  const auto start = std::chrono::steady_clock::now();
  const ShCoefficients coefficients = project_sh(loaded.map->image());
  const double elapsed =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Output out(file);
  out.write(api::sh_json(coefficients, request, elapsed, false) + "\n");
  out.finish();
}

}  // namespace

Command sh_command() {
  return {"sh", kSynopsis, "spherical harmonics of a map: radiance and irradiance (JSON)", {}, help, run};
}

}  // namespace lp::cli
