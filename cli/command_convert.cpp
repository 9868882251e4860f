// lightprobe convert IN OUT: an image from one format to another, PNG tone mapped as the API's images.
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_input.hpp"
#include "cli/image_output.hpp"
#include "cli/output.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "convert IN OUT [options]";

std::string help() {
  return "Reads IN (OpenEXR, PFM or Radiance HDR, told by its bytes) and writes OUT in the format of its\n"
         "extension or --format (OUT - is standard output). EXR and PFM keep every float exactly; PNG is\n"
         "tone mapped as the API's images are (exposure in stops, then gamma or the sRGB curve).\n\n" +
         image_params_help();
}

void run(Arguments& args) {
  args.expect_positional(2, kSynopsis);
  const std::string& out_file = args.positional()[1];
  const api::PreviewParams params = take_image_params(args, out_file);
  args.expect_all_taken("convert");
  const DecodedImage in = read_input_image(args.positional()[0]);
  const auto bytes = write_image(in.image, params.format, params.tone);
  Output out(out_file);
  out.write(bytes);
  out.finish();
}

}  // namespace

Command convert_command() {
  return {"convert", kSynopsis, "an image between OpenEXR, PFM, Radiance HDR and PNG", {}, help, run};
}

}  // namespace lp::cli
