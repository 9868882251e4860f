// lightprobe convert IN OUT: an image from one format to another, PNG tone mapped as the API's images, and
// from one projection of a map to another, resampled as the API's projections are.
#include <fmt/format.h>

#include "api/parameters.hpp"
#include "api/projection_params.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_input.hpp"
#include "cli/image_output.hpp"
#include "cli/output.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/projection_exr.hpp"
#include "engine/projection/reproject.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "convert IN OUT [options]";

std::string help() {
  return "Reads IN (OpenEXR, PFM or Radiance HDR, told by its bytes) and writes OUT in the format of its\n"
         "extension or --format (OUT - is standard output). EXR and PFM keep every float exactly; PNG is\n"
         "tone mapped as the API's images are (exposure in stops, then gamma or the sRGB curve).\n\n"
         "A map changes projection when --input-projection and --projection differ (or with --size), each\n"
         "texel the solid-angle-weighted mean of the map over its footprint, as GET\n"
         "/api/v1/envmaps/{id}/image answers; its description states the layouts and the cube's faces.\n"
         "IN's lat-long width is its width, 4N for a cube or cross of faces N, 2N for a square of side N;\n"
         "a lat-long OUT is that wide and half as high.\n\n" +
         option_line("--input-projection NAME",
                     choices(Projection::LatLong) +
                         ":\nIN's layout, as `projection` of POST /api/v1/envmaps "
                         "(a cross is 4:3,\na cube strip 6:1, a square map square)") +
         option_line("--projection NAME", choices(Projection::LatLong) + ":\nOUT's layout") +
         option_line("--size N",
                     fmt::format("OUT's face size (cube, cross) or side (octahedral, equal-area), in\n"
                                 "[{}, {}] (default: IN's lat-long width / 4, or / 2); not for latlong",
                                 limits::kProjectionSize.min, limits::kProjectionSize.max)) +
         option_line("--face NAME",
                     enum_names_joined<CubeFace>() + ": with --projection cube, that face alone") +
         image_params_help();
}

// IN in its projection, as a lat-long map when OUT is one, else in OUT's projection at the size asked.
Image reprojected(const Image& in, Projection from, const api::ProjectionParams& to) {
  const int64_t max_pixels = api::kMaxPixels.fallback;
  const int latlong_width =
      from == Projection::LatLong
          ? in.width()
          : api::input_latlong_width(from, in.width(), in.height(), max_pixels, "input_projection");
  if (to.projection == Projection::LatLong)
    return from == Projection::LatLong ? in : reproject(in, from, Projection::LatLong, latlong_width);
  const int size = api::projection_image_size(to, latlong_width, max_pixels);
  if (!to.face) return reproject(in, from, to.projection, size);
  return cube_strip_face(reproject(in, from, Projection::Cube, size), int(*to.face));
}

void run(Arguments& args) {
  args.expect_positional(2, kSynopsis);
  const std::string& out_file = args.positional()[1];
  const api::PreviewParams params = take_image_params(args, out_file);
  const Projection from =
      api::parse_input_projection(args.take_query({"input-projection"}), "input_projection");
  const api::ProjectionParams to =
      api::parse_projection_params(args.take_query({"projection", "size", "face"}));
  args.expect_all_taken("convert");
  const DecodedImage in = read_input_image(args.positional()[0]);
  const ExrEnvmap envmap = to.face ? ExrEnvmap::None : exr_envmap(to.projection);  // a face is no map
  const auto bytes = write_image_envmap(reprojected(in.image, from, to), params.format, params.tone, envmap);
  Output out(out_file);
  out.write(bytes);
  out.finish();
}

}  // namespace

Command convert_command() {
  return {
      "convert", kSynopsis, "an image between OpenEXR, PFM, Radiance HDR and PNG, a map between projections",
      {},        help,      run};
}

}  // namespace lp::cli
