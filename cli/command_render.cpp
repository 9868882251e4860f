// lightprobe render SCENE.json: path-traces the scene of a render request to an image, with a progress
// bar on standard error.
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <atomic>
#include <optional>

#include "api/parameters.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_output.hpp"
#include "cli/output.hpp"
#include "cli/progress_bar.hpp"
#include "cli/scene_file.hpp"
#include "engine/render/pass_schedule.hpp"
#include "engine/render/renderer.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "render SCENE.json [options]";

std::string help() {
  const api::RequestLimits l;
  return "Renders SCENE.json, the JSON body of POST /api/v1/renders (the same fields, defaults, limits and\n"
         "errors), on all cores, showing a progress bar on standard error. In the scene file, \"envmap\" is "
         "a\n"
         "map file (OpenEXR, PFM, Radiance HDR) or `default`, the built-in procedural sky, and a mesh's\n"
         "\"path\" a .gltf, .glb or .obj model file; relative paths are taken from the scene file's folder.\n"
         "Other options set the request's top-level fields, replacing the file's:\n"
         "--width, --height, --spp, --max-depth, --seed, --mipmaps, --normal-maps, --sampling, "
         "--tone-mapping,\n"
         "and --envmap (a path relative to the working directory).\n\n" +
         fmt::format("Limits: width up to {}, height up to {}, spp up to {}, max_depth up to {}.\n\n",
                     l.max_render_width, l.max_render_height, l.max_render_spp, l.max_render_depth) +
         image_params_help(ToneOption::RequestField) +
         option_line("--threads N",
                     fmt::format("{}, in [{}, {}] (default: {})", api::kThreads.help, api::kThreads.range.min,
                                 api::kThreads.range.max, api::kThreads.default_text)) +
         option_line("-q, --quiet", "no progress bar") + output_help();
}

std::optional<tbb::global_control> thread_limit(Arguments& args) {
  const auto& t = api::kThreads;
  const int64_t threads =
      api::query_int(args.take_query({"threads"}), "threads", 0, t.range.min, t.range.max);
  if (threads == 0) return std::nullopt;
  return std::optional<tbb::global_control>(std::in_place, tbb::global_control::max_allowed_parallelism,
                                            size_t(threads));
}

Image render(const SceneRender& scene, bool progress) {
  const auto& r = scene.request;
  render::Renderer renderer(r.scene, r.lighting, r.settings, scene.envmap);
  // The passes a job runs (an adaptive render's uniform warm-up first), each up to all of the spp.
  ProgressBar bar("render", int64_t(renderer.tile_count()) * r.settings.spp, progress);
  const std::atomic<bool> never{false};
  for (const render::RenderPass& pass : render::render_passes(r.settings, r.settings.spp)) {
    const auto on_tile = [&bar, spp = pass.spp] { bar.advance(spp); };
    renderer.render(pass, never, on_tile);
  }
  bar.finish();
  return renderer.image();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const bool quiet = args.take_switch("quiet");
  const auto file = args.take("output");
  api::PreviewParams image = take_image_params(args, file, ToneOption::RequestField);
  const auto threads = thread_limit(args);
  const SceneRender scene =
      read_scene_file(args.positional()[0], args.take_rest_as_json(), api::RequestLimits{});
  image.tone.curve = scene.request.tone_mapping;
  const auto bytes = write_image(render(scene, !quiet), image.format, image.tone);
  Output out(file);
  out.write(bytes);
  out.finish();
}

}  // namespace

Command render_command() {
  return {"render",  kSynopsis, "path-trace a scene (the JSON body of POST /api/v1/renders) to an image",
          {"quiet"}, help,      run};
}

}  // namespace lp::cli
