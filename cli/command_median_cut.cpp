// lightprobe median-cut MAP: Debevec's median cut, as POST /api/v1/envmaps/{id}/median-cut answers it,
// or as light lists for other renderers.
#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/light_export.hpp"
#include "api/median_cut_request.hpp"
#include "api/median_cut_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/light_lists.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"
#include "engine/envmap/illuminance.hpp"

namespace lp::cli {

// The lists only this tool writes; --format takes these and the API's light formats (api/light_export.hpp).
enum class LightListFormat { Csv, Pbrt };
constexpr auto enum_entries(LightListFormat) {
  return std::to_array<EnumEntry<LightListFormat>>(
      {{LightListFormat::Csv, "csv"}, {LightListFormat::Pbrt, "pbrt"}});
}

namespace {

constexpr std::string_view kSynopsis = "median-cut MAP [options]";

// The answer in the format --format and --frame name.
std::string encode(const MedianCutResult& result, const EnvMap& map, api::Query format) {
  if (const auto list = format.count("format") ? parse_enum<LightListFormat>(format.find("format")->second)
                                               : std::nullopt) {
    if (format.count("frame")) throw api::invalid_field("frame", "applies to format mitsuba only");
    return *list == LightListFormat::Csv ? lights_csv(result) : lights_pbrt(result);
  }
  const api::LightExportQuery e = api::parse_light_export_query(format);
  if (e.format == api::LightFormat::Answer)
    return api::median_cut_json(result, result.elapsed_ms, false) + "\n";
  return api::export_lights(api::median_cut_light_set(result, upper_hemisphere_illuminance(map)), e.format,
                            e.frame);
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
                     choices(api::LightFormat::Answer) + " or " + enum_names_joined<LightListFormat>() +
                         ": the API's JSON, a file for another tool\n"
                         "(as POST .../median-cut?format=NAME: Mitsuba 3 scene, Blender script, USD\n"
                         "DistantLights, glTF KHR_lights_punctual), CSV with a header in the world\n"
                         "frame (z up), or pbrt-v4 `LightSource \"distant\"` lines to Include after\n"
                         "WorldBegin.") +
         option_line("--frame NAME", choices(api::MitsubaFrame::Mitsuba) + ": the frame of format mitsuba") +
         output_help();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const api::Query format = args.take_query({"format", "frame"});
  const auto file = args.take("output");
  const api::RequestLimits limits;
  const MedianCutParams params = api::parse_median_cut_request(args.take_rest_as_json().dump(), limits);
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  api::check_count_fits(params, loaded.map->image().pixel_count());
  const std::string text = encode(median_cut(*loaded.map, params), *loaded.map, format);
  Output out(file);
  out.write(text);
  out.finish();
}

}  // namespace

Command median_cut_command() {
  return {"median-cut",
          kSynopsis,
          "directional lights by median cut (JSON, CSV, pbrt-v4, Mitsuba 3, Blender, USD, glTF)",
          {},
          help,
          run};
}

}  // namespace lp::cli
