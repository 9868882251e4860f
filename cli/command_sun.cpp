// lightprobe sun MAP: the map's sun, as POST /api/v1/envmaps/{id}/sun answers it, and optionally its
// residual map written to a file.
#include <fmt/format.h>

#include <algorithm>

#include "api/api_error.hpp"
#include "api/light_export.hpp"
#include "api/sun_request.hpp"
#include "api/sun_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_output.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"
#include "engine/core/limits.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/image/image_io.hpp"

namespace lp::cli {

namespace {

constexpr std::string_view kSynopsis = "sun MAP [options]";

// One line per parameter of engine/sun/sun_params.hpp: --min-share F for min_share.
std::string sun_parameter_help() {
  const SunParams d;
  std::string out;
  for (const SunField& f : kSunFields) {
    std::string option = std::string("--") + f.name + " F";
    std::replace(option.begin(), option.end(), '_', '-');
    out += option_line(
        option, fmt::format("{},\nin [{}, {}] (default {})", f.help, f.range.min, f.range.max, d.*f.member));
  }
  return out;
}

std::string help() {
  return "The map's dominant compact emitter: its direction, angular radius, colour and irradiance, and the\n"
         "powers of the map, the residual (the map without the sun) and the sun, which add up exactly; the\n"
         "answer of POST /api/v1/envmaps/{id}/sun, with `residual` the file written or null.\n\n" +
         sun_parameter_help() +
         option_line("--residual FILE",
                     "write the residual map if there is a sun\n(format from the extension: " +
                         enum_names_joined<ImageFormat>() + ")") +
         option_line("--format NAME", choices(api::LightFormat::Answer) +
                                          ": the API's JSON, or the sun as a light for another tool\n"
                                          "(as POST .../sun?format=NAME)") +
         option_line("--frame NAME", choices(api::MitsubaFrame::Mitsuba) + ": the frame of format mitsuba") +
         invalid_pixel_policy_help() + output_help();
}

ImageFormat residual_format(const std::string& file) {
  const auto format = image_format_of_name(file);
  if (!format)
    throw api::invalid_field("residual", fmt::format("cannot tell an image format from the name '{}' ({})",
                                                     api::excerpt(file), enum_names_joined<ImageFormat>()));
  return *format;
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const api::LightExportQuery answer = api::parse_light_export_query(args.take_query({"format", "frame"}));
  const auto file = args.take("output");
  const auto residual_file = args.take("residual");
  const ImageFormat format = residual_file ? residual_format(*residual_file) : ImageFormat::Exr;
  const SunParams params = api::parse_sun_request(args.take_rest_as_json().dump());
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  const SunExtraction extraction = extract_sun(*loaded.map, params);
  std::optional<std::string> written;
  if (residual_file && extraction.residual) {
    Output residual(residual_file);
    residual.write(write_image(extraction.residual->image(), format));
    residual.finish();
    written = residual_file;
  }
  Output out(file);
  if (answer.format != api::LightFormat::Answer) {
    const double illuminance = upper_hemisphere_illuminance(*loaded.map);
    out.write(api::export_lights(extraction.sun ? api::sun_light_set(*extraction.sun, illuminance)
                                                : api::no_sun_light_set(extraction.reason, illuminance),
                                 answer.format, answer.frame));
    out.finish();
    return;
  }
  out.write(api::sun_json(extraction, written, false).dump(2) + "\n");
  out.finish();
}

}  // namespace

Command sun_command() {
  return {"sun", kSynopsis, "the map's sun and the map without it (JSON, and the residual map)",
          {},    help,      run};
}

}  // namespace lp::cli
