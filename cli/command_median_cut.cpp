// lightprobe median-cut MAP: Debevec's median cut, as POST /api/v1/envmaps/{id}/median-cut answers it,
// or as light lists for other renderers.
#include <fmt/format.h>

#include "api/median_cut_request.hpp"
#include "api/median_cut_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/light_lists.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"

namespace lp::cli {

enum class LightListFormat { Json, Csv, Pbrt, Mitsuba };
constexpr auto enum_entries(LightListFormat) {
  return std::to_array<EnumEntry<LightListFormat>>({{LightListFormat::Json, "json"},
                                                    {LightListFormat::Csv, "csv"},
                                                    {LightListFormat::Pbrt, "pbrt"},
                                                    {LightListFormat::Mitsuba, "mitsuba"}});
}

namespace {

constexpr std::string_view kSynopsis = "median-cut MAP [options]";

std::string encode(const MedianCutResult& result, LightListFormat format) {
  switch (format) {
    case LightListFormat::Csv:
      return lights_csv(result);
    case LightListFormat::Pbrt:
      return lights_pbrt(result);
    case LightListFormat::Mitsuba:
      return lights_mitsuba(result);
    case LightListFormat::Json:
      break;
  }
  return api::median_cut_json(result, result.elapsed_ms, false) + "\n";
}

std::string help() {
  const api::RequestLimits limits;
  const MedianCutParams d = api::parse_median_cut_request("", limits);
  return "Debevec's median cut: the map as directional lights of nearly equal energy whose powers add up\n"
         "to the map's power; the answer of POST /api/v1/envmaps/{id}/median-cut.\n\n" +
         option_line("--count N", fmt::format("lights, in [{}, {}] (default {}), at most the map's pixels",
                                              api::kLightCount.range.min, limits.max_lights, d.count)) +
         option_line("--split NAME", choices(d.split)) +
         option_line("--placement NAME", choices(d.placement)) +
         option_line("--luminance NAME", choices(d.luminance)) + invalid_pixel_policy_help() +
         option_line("--format NAME",
                     choices(LightListFormat::Json) +
                         ": the API's JSON, CSV with a header,\n"
                         "pbrt-v4 `LightSource \"distant\"` lines to Include after WorldBegin,\n"
                         "or a Mitsuba 3 scene of `directional` emitters to <include>.\n"
                         "Directions are in Lightprobe's world frame (z up).") +
         output_help();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const LightListFormat format = args.take_enum("format", LightListFormat::Json);
  const auto file = args.take("output");
  const api::RequestLimits limits;
  const MedianCutParams params = api::parse_median_cut_request(args.take_rest_as_json().dump(), limits);
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  api::check_count_fits(params, loaded.map->image().pixel_count());
  const std::string text = encode(median_cut(*loaded.map, params), format);
  Output out(file);
  out.write(text);
  out.finish();
}

}  // namespace

Command median_cut_command() {
  return {"median-cut", kSynopsis, "directional lights by median cut (JSON, CSV, pbrt-v4, Mitsuba 3)",
          {},           help,      run};
}

}  // namespace lp::cli
