#include "cli/render_fields.hpp"

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "cli/help.hpp"

namespace lp::cli {
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
  return r;
}

std::string request_options_help() {
  return option_line("--background B",
                     "map (default), transparent (PNG and EXR with alpha), or a linear colour [r,g,b]") +
         option_line("--clamp C", "bound on the radiance of indirect samples (default: none)") +
         option_line("--ground", "add a shadow-catcher ground under the model") +
         option_line("--denoise",
                     "denoise the colour after the last pass (Open Image Denoise's network, with the\n"
                     "albedo and normal it then computes); a turntable's frames are denoised unless\n"
                     "--no-denoise");
}

}  // namespace lp::cli
