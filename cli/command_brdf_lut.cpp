// lightprobe brdf-lut: the split-sum DFG table, as GET /api/v1/brdf-lut answers it.
#include <fmt/format.h>

#include "api/brdf_lut_request.hpp"
#include "api/query_policy.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/output.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "brdf-lut -o FILE [options]";

std::string help() {
  return "The split-sum DFG table of GGX (alpha = roughness^2): n.v across, roughness down (row 0 the\n"
         "smoothest); red and green scale and bias, or with --multiscatter true Filament's layout (bias,\n"
         "scale + bias). The file of GET /api/v1/brdf-lut.\n\n" +
         option_line("--size N",
                     fmt::format("texels per side, in [{}, {}] (default {})", api::kDfgLutSize.min,
                                 api::kDfgLutSize.max, api::kDefaultDfgLutSize)) +
         option_line("--multiscatter BOOL",
                     "Filament's layout for multiple-scattering compensation (default false)") +
         option_line("--format NAME", choices(ImageFormat::Exr) + " (PNG stores the channels linearly)") +
         output_help();
}

void run(Arguments& args) {
  args.expect_positional(0, kSynopsis);
  const auto file = args.take("output");
  const api::Query query = args.take_rest_as_query();
  api::QueryPolicy("GET", "/api/v1/brdf-lut").check(query);
  const api::BrdfLutRequest r = api::parse_brdf_lut_query(query);
  const DfgLut lut = make_dfg_lut(r.size, r.multiscatter);
  Output out(file);
  out.write(write_image(api::dfg_lut_image(lut), r.format, api::kLinearPng));
  out.finish();
}

}  // namespace

Command brdf_lut_command() {
  return {"brdf-lut", kSynopsis, "the split-sum DFG table of GGX (EXR, PFM, HDR or PNG)", {}, help, run};
}

}  // namespace lp::cli
