#include "cli/image_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "cli/help.hpp"

namespace lp::cli {

std::optional<ImageFormat> image_format_of_name(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return parse_enum<ImageFormat>(std::string_view(extension).substr(std::min<size_t>(1, extension.size())));
}

api::PreviewParams take_image_params(Arguments& args, const std::optional<std::string>& file,
                                     ToneOption tone) {
  api::Query query = args.take_query({"format", "exposure", "gamma"});
  if (tone == ToneOption::Own) query.merge(args.take_query({"tone-mapping"}));
  if (!query.count("format") && file && *file != "-") {
    const auto format = image_format_of_name(*file);
    if (!format)
      throw api::ApiError(api::ErrorCode::BadRequest,
                          fmt::format("cannot tell an image format from the name '{}': give --format ({})",
                                      api::excerpt(*file), enum_names_joined<ImageFormat>()));
    query.emplace("format", enum_name(*format));
  }
  return api::parse_preview_params(query);
}

std::string image_params_help(ToneOption tone) {
  const api::PreviewParams d = api::parse_preview_params({});
  const ToneCurve curve =
      tone == ToneOption::Own ? api::kToneMapping.fallback : api::kRenderToneMapping.fallback;
  return option_line("--format NAME", enum_names_joined<ImageFormat>() +
                                          " (default: the output file's extension, else " +
                                          enum_name(d.format) + ")") +
         option_line("--exposure STOPS",
                     fmt::format("png only: scale by 2^STOPS first, in [{}, {}] (default {})",
                                 api::kExposure.range.min, api::kExposure.range.max, d.tone.exposure)) +
         option_line("--tone-mapping NAME",
                     fmt::format("png only: the tone curve after the exposure (default {}):\n{}",
                                 enum_name(curve), enum_names_joined<ToneCurve>())) +
         option_line("--gamma G", fmt::format("png only: gamma in (0, {}] (default: the sRGB curve)",
                                              api::kGamma.range.max));
}

}  // namespace lp::cli
