// lightprobe info MAP | MODEL: a map's metadata, as GET /api/v1/envmaps/{id} answers it, or a model's
// description, as an asset's record gives it (GET /api/v1/assets/{name}).
#include "api/envmap_schema.hpp"
#include "api/model_info_schema.hpp"
#include "api/render_request.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"
#include "engine/model/model_loader.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "info MAP|MODEL [options]";

std::string help() {
  return "For a map: its size, power [r, g, b] (radiance integrated over the sphere), mean radiance,\n"
         "upper-hemisphere illuminance (Rec. 709 luminance times cos theta over z > 0), largest\n"
         "luminance and the pixels its invalid-pixel policy changed: the metadata of\n"
         "GET /api/v1/envmaps/{id}, as JSON, without the server's `created` and `memory_bytes`; `id` and\n"
         "`name` are the file's stem.\n\n"
         "For a model (.glb, .gltf or .obj): its `format` and the description an asset's record gives\n"
         "(GET /api/v1/assets/{name}): bounds in the world frame (z up; glTF's (x, y, z) is (x, -z, y)),\n"
         "triangles, vertices, meshes, materials and their features, textures, cameras, the glTF\n"
         "extensions used and warnings for what is ignored. It is loaded as a render loads it, under the\n"
         "server's default model limits: a model a render would refuse fails with invalid_model.\n\n" +
         invalid_pixel_policy_help() + output_help();
}

api::Json model_description(const std::string& file, const std::string& format) {
  try {
    api::Json out = {{"format", format}};
    out.update(api::model_info_json(describe_model(load_model(file, api::model_limits({})))));
    return out;
  } catch (const Error& e) {
    throw api::invalid_model(e);
  }
}

api::Json map_metadata(const std::string& argument, InvalidPixelPolicy policy) {
  const LoadedMap loaded = load_map(argument, policy);
  api::Json metadata =
      api::envmap_metadata({loaded.name, loaded.name, loaded.format, loaded.source, {}}, *loaded.map);
  metadata.erase("created");
  metadata.erase("memory_bytes");  // what the server holds for the map
  return metadata;
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const auto file = args.take("output");
  args.expect_all_taken("info");
  const std::string& argument = args.positional()[0];
  const std::string format = model_format(argument);
  const api::Json document =
      format.empty() ? map_metadata(argument, policy) : model_description(argument, format);
  Output out(file);
  out.write(document.dump(2) + "\n");
  out.finish();
}

}  // namespace

Command info_command() {
  return {"info",
          kSynopsis,
          "a map's size, power and mean radiance, or a model's bounds, counts and materials (JSON)",
          {},
          help,
          run};
}

}  // namespace lp::cli
