// lightprobe denoise COLOR -o OUT: Open Image Denoise's network on a rendered image, with its first-hit
// albedo and normal when given.
#include "api/api_error.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_input.hpp"
#include "cli/image_output.hpp"
#include "cli/output.hpp"
#include "cli/thread_option.hpp"
#include "engine/core/error.hpp"
#include "engine/denoise/denoiser.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "denoise COLOR -o OUT [--albedo A] [--normal N] [--ldr] [options]";

std::string help() {
  return "Denoises COLOR (OpenEXR, PFM or Radiance HDR, told by its bytes; linear RGB) with Intel Open "
         "Image\n"
         "Denoise's trained U-Net (its rt filters), on the CPU. HDR colour is scaled by OIDN's\n"
         "autoexposure; --ldr is for colour in [0, 1]. The weights are read from "
         "LIGHTPROBE_DENOISE_WEIGHTS,\n"
         "else the installed share/lightprobe/denoise.\n\n" +
         option_line("--albedo FILE", "first-hit albedo in [0, 1], COLOR's size") +
         option_line("--normal FILE", "first-hit normal in [-1, 1], COLOR's size (needs --albedo)") +
         option_line("--ldr", "COLOR is low dynamic range, in [0, 1]") + threads_help() +
         image_params_help() + output_help();
}

std::optional<DecodedImage> read_optional(const std::optional<std::string>& file) {
  if (!file) return std::nullopt;
  return read_input_image(*file);
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const auto file = args.take("output");
  const auto albedo_file = args.take("albedo");
  const auto normal_file = args.take("normal");
  denoise::DenoiseOptions options;
  options.range = args.take_switch("ldr") ? denoise::Range::Ldr : denoise::Range::Hdr;
  options.threads = take_threads(args);
  const api::PreviewParams params = take_image_params(args, file);
  args.expect_all_taken("denoise");
  if (normal_file && !albedo_file)
    throw api::ApiError(api::ErrorCode::BadRequest,
                        "--normal needs --albedo (OIDN has no colour+normal filter)");

  const denoise::Denoiser denoiser;
  if (!denoiser.available())
    throw Error(ErrorKind::NotFound,
                "denoiser weights not found in " + denoiser.weights_dir().string() +
                    " (set LIGHTPROBE_DENOISE_WEIGHTS to the folder of the rt_*.tza files)");
  const DecodedImage color = read_input_image(args.positional()[0]);
  const auto albedo = read_optional(albedo_file);
  const auto normal = read_optional(normal_file);
  Image result;
  try {
    result = denoiser.run(
        {&color.image, albedo ? &albedo->image : nullptr, normal ? &normal->image : nullptr}, options);
  } catch (const denoise::DenoiseError& e) {
    throw api::ApiError(api::ErrorCode::BadRequest, e.what());
  }
  Output out(file);
  out.write(write_image(result, params.format, params.tone));
  out.finish();
}

}  // namespace

Command denoise_command() {
  return {"denoise", kSynopsis, "Open Image Denoise's network on a rendered image (with albedo, normal)",
          {"ldr"},   help,      run};
}

}  // namespace lp::cli
