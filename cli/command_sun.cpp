// lightprobe sun MAP: the map's sun, as POST /api/v1/envmaps/{id}/sun answers it, and optionally its
// residual map written to a file.
#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/sun_request.hpp"
#include "api/sun_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_output.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"
#include "engine/core/limits.hpp"
#include "engine/image/image_io.hpp"

namespace lp::cli {

enum class SunFormat { Json };
constexpr auto enum_entries(SunFormat) {
  return std::to_array<EnumEntry<SunFormat>>({{SunFormat::Json, "json"}});
}

namespace {

constexpr std::string_view kSynopsis = "sun MAP [options]";

template <class T>
std::string range_line(std::string_view option, const Range<T>& range, T fallback, std::string_view what) {
  return option_line(option,
                     fmt::format("{}, in [{}, {}] (default {})", what, range.min, range.max, fallback));
}

std::string help() {
  const SunParams d = api::parse_sun_request("");
  return "The map's dominant compact emitter: its direction, angular radius, colour and irradiance, and the\n"
         "powers of the map, the residual (the map without the sun) and the sun, which add up exactly; the\n"
         "answer of POST /api/v1/envmaps/{id}/sun, with `residual` the file written or null.\n\n" +
         range_line("--threshold F", limits::kSunThreshold, d.threshold,
                    "core pixels' least share of the peak") +
         range_line("--max-radius-deg A", limits::kSunMaxRadiusDeg, d.max_radius_deg,
                    "largest sun's radius") +
         range_line("--min-share F", limits::kSunMinShare, d.min_share, "least share of the map's power") +
         option_line("--residual FILE",
                     "write the residual map if there is a sun\n(format from the extension: " +
                         enum_names_joined<ImageFormat>() + ")") +
         option_line("--format NAME", choices(SunFormat::Json)) + invalid_pixel_policy_help() + output_help();
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
  args.take_enum("format", SunFormat::Json);
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
  out.write(api::sun_json(extraction, written, false).dump(2) + "\n");
  out.finish();
}

}  // namespace

Command sun_command() {
  return {"sun", kSynopsis, "the map's sun and the map without it (JSON, and the residual map)",
          {},    help,      run};
}

}  // namespace lp::cli
