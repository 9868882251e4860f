// lightprobe info MAP: the map's metadata, as GET /api/v1/envmaps/{id} answers it.
#include "api/envmap_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "info MAP [options]";

std::string help() {
  return "The map's size, power [r, g, b] (radiance integrated over the sphere), mean radiance, largest\n"
         "luminance and the pixels its invalid-pixel policy changed: the metadata of\n"
         "GET /api/v1/envmaps/{id}, as JSON, without the server's `created` and `memory_bytes`; `id` and\n"
         "`name` are the file's stem.\n\n" +
         invalid_pixel_policy_help() + output_help();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const auto file = args.take("output");
  args.expect_all_taken("info");
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  Output out(file);
  api::Json metadata =
      api::envmap_metadata({loaded.name, loaded.name, loaded.format, loaded.source, {}}, *loaded.map);
  metadata.erase("created");
  metadata.erase("memory_bytes");  // what the server holds for the map
  out.write(metadata.dump(2) + "\n");
  out.finish();
}

}  // namespace

Command info_command() {
  return {"info", kSynopsis, "a map's size, power, mean radiance and invalid pixels (JSON)", {}, help, run};
}

}  // namespace lp::cli
