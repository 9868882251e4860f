#include "cli/render_fields.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "api/render_request.hpp"
#include "cli/help.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::cli {
namespace {

// "albedo,depth" as the JSON array of those names (a JSON array as itself); the request names what is wrong.
api::Json pass_names(const std::string& value) {
  if (value.starts_with('[')) {
    api::Json array = api::Json::parse(value, nullptr, false);
    if (array.is_array()) return array;
  }
  api::Json names = api::Json::array();
  size_t start = 0;
  for (size_t comma; (comma = value.find(',', start)) != std::string::npos; start = comma + 1)
    names.push_back(value.substr(start, comma - start));
  names.push_back(value.substr(start));
  return names;
}

}  // namespace

RequestOptions take_request_options(Arguments& args) {
  RequestOptions r;
  const bool denoise = args.take_switch(kDenoiseSwitch), no_denoise = args.take_switch(kNoDenoiseSwitch);
  if (denoise && no_denoise)
    throw api::ApiError(api::ErrorCode::BadRequest, "give --denoise or --no-denoise, not both");
  if (denoise || no_denoise) r.fields[api::kRenderDenoise.name] = denoise;
  if (args.take_switch(kGroundSwitch)) {
    r.objects.objects.push_back({{"type", "ground"}, {"shadow_catcher", true}});
    r.objects.options = "--ground";
  }
  if (const auto passes = args.take(api::kPassesField)) r.fields[api::kPassesField] = pass_names(*passes);
  return r;
}

std::string request_options_help() {
  return option_line("--background B",
                     "map (default), transparent (PNG, WebP and EXR with alpha; JPEG over white),\n"
                     "or a linear colour [r,g,b]") +
         option_line("--clamp C", "bound on the radiance of indirect samples (default: none)") +
         option_line("--ground", "add a shadow-catcher ground under the model") +
         option_line(fmt::format("--{} P,...", api::kPassesField),
                     fmt::format("auxiliary passes kept beside the colour, of {}:\n"
                                 "channels of an EXR output (as pass=all), else one file each beside\n"
                                 "-o FILE (thumb.albedo.png, thumb.depth.png beside thumb.png)",
                                 enum_names_joined<render::AuxPass>())) +
         option_line("--denoise",
                     "denoise the colour after the last pass (Open Image Denoise's network, with the\n"
                     "albedo and normal it then computes); a MODEL's picture and a turntable's frames\n"
                     "are denoised unless --no-denoise");
}

}  // namespace lp::cli
