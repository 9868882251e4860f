// lightprobe render SCENE.json | MODEL: path-traces the scene of a render request, or one framed model, to
// an image, or to the frames of a turntable, with progress on standard error.
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <atomic>
#include <memory>
#include <optional>

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/image_output.hpp"
#include "cli/output.hpp"
#include "cli/progress_bar.hpp"
#include "cli/render_fields.hpp"
#include "cli/render_picture.hpp"
#include "cli/scene_file.hpp"
#include "cli/thread_option.hpp"
#include "cli/turntable_files.hpp"
#include "cli/turntable_options.hpp"
#include "engine/denoise/denoiser.hpp"
#include "engine/render/pass_schedule.hpp"
#include "engine/render/renderer.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kSynopsis = "render SCENE.json|MODEL [options]";

std::string help() {
  const api::RequestLimits l;
  return "Renders SCENE.json, the JSON body of POST /api/v1/renders (the same fields, defaults, limits and\n"
         "errors), or MODEL, a .gltf, .glb or .obj file: the body whose scene is that one model with its "
         "own\n"
         "materials, framed by the default camera fit, under the built-in sky unless --envmap, and denoised\n"
         "unless --no-denoise (a thumbnail). In the scene file, \"envmap\" is a map file (OpenEXR, PFM,\n"
         "Radiance HDR) or `default`, the built-in procedural sky, and a mesh's \"path\" a model file;\n"
         "relative paths are taken from the scene file's folder. Runs on all cores, showing progress on\n"
         "standard error: a bar with the rate and the time left on a terminal, else a line at each 10%.\n\n"
         "Other options set the request's top-level fields, replacing the file's: --width, --height, --spp,\n"
         "--max-depth, --seed, --mipmaps, --normal-maps, --sampling, --tone-mapping, --background, --clamp,\n"
         "and --envmap (a path relative to the working directory).\n\n" +
         fmt::format("Limits: width up to {}, height up to {}, spp up to {}, max_depth up to {}.\n\n",
                     l.max_render_width, l.max_render_height, l.max_render_spp, l.max_render_depth) +
         image_params_help(ToneOption::RequestField) + request_options_help() + turntable_help() +
         threads_help() + option_line("-q, --quiet", "no progress") + output_help() +
         "\nAn image is not written to a terminal: give -o FILE or redirect standard output (-o - insists).\n"
         "A missing output folder is refused before rendering.\n";
}

std::optional<tbb::global_control> thread_limit(Arguments& args) {
  const int threads = take_threads(args);
  if (threads == 0) return std::nullopt;
  return std::optional<tbb::global_control>(std::in_place, tbb::global_control::max_allowed_parallelism,
                                            size_t(threads));
}

// The denoiser of the installed or source tree's weights; a 503 denoiser_unavailable without them.
std::unique_ptr<denoise::Denoiser> available_denoiser() {
  auto denoiser = std::make_unique<denoise::Denoiser>();
  if (!denoiser->available())
    throw api::ApiError(
        api::ErrorCode::DenoiserUnavailable,
        fmt::format("no denoiser weights in {} (set LIGHTPROBE_DENOISE_WEIGHTS, or render with "
                    "--no-denoise)",
                    denoiser->weights_dir().string()));
  return denoiser;
}

// The finished render's colour denoised with its albedo and normal.
Image denoised(const render::Renderer& renderer, const denoise::Denoiser& denoiser) {
  const Image color = renderer.image(), albedo = renderer.image(render::AuxPass::Albedo),
              normal = renderer.image(render::AuxPass::Normal);
  return denoiser.run({&color, &albedo, &normal});
}

// Renders the frames (the same scene seen by each camera) one after the other, with one progress over
// all of them, handing each one's images to `done` as it finishes.
template <class Done>
void render_frames(const SceneRender& r, const std::vector<render::Camera>& cameras, ProgressStyle style,
                   Done&& done) {
  const render::RenderSettings& s = r.request.settings;
  const render::RenderSettings written = written_settings(r.request);
  const int64_t frames = int64_t(cameras.size());
  const auto denoiser = r.request.denoise ? available_denoiser() : nullptr;
  std::optional<ProgressBar> bar;
  render::SceneDesc scene = r.request.scene;
  for (int64_t i = 0; i < frames; ++i) {
    scene.camera = cameras[size_t(i)];
    render::Renderer renderer(scene, r.request.lighting, s, r.envmap);
    // Progress in tile-samples: each pass adds its spp to every tile (an adaptive pass as a mean).
    const int64_t tiles = renderer.tile_count();
    if (!bar)
      bar.emplace("render", frames * tiles * s.spp, style,
                  ProgressBar::Rate{double(s.width) * s.height / double(tiles), "samples"});
    if (frames > 1) bar->set_label(fmt::format("render frame {}/{}", i + 1, frames));
    const std::atomic<bool> never{false};
    for (const render::RenderPass& pass : render::render_passes(s, s.spp))
      renderer.render(pass, never, [&bar, spp = pass.spp] { bar->advance(spp); });
    done(i, RenderedImages(renderer, written,
                           r.request.denoise ? std::optional(denoised(renderer, *denoiser)) : std::nullopt));
  }
  if (bar) bar->finish();
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const ProgressStyle progress = progress_style(args.take_switch("quiet"));
  const auto file = args.take("output");
  const auto turntable = take_turntable(args);
  api::PreviewParams image =
      take_image_params(args, turntable ? std::nullopt : file, ToneOption::RequestField);
  const auto threads = thread_limit(args);
  const RequestOptions request = take_request_options(args);
  api::Json fields = args.take_rest_as_json();
  fields.update(request.fields);
  if (turntable) {
    require_turntable_folder(file);
  } else {
    refuse_binary_to_terminal(file);
    if (file) require_folder_of(*file);
  }
  const SceneRender scene =
      read_scene(args.positional()[0], fields, request.objects, turntable, api::RequestLimits{});
  image.tone.curve = scene.request.tone_mapping;
  const render::RenderSettings s = written_settings(scene.request);
  refuse_unwritten_passes(s, image.format, file, turntable.has_value());
  if (turntable) {
    TurntableFiles out(*file, *scene.turntable, scene, image);
    render_frames(scene, out.cameras(), progress, [&](int64_t i, const RenderedImages& frame) {
      out.write(i, encode_picture(frame, image));
    });
    out.finish();
    return;
  }
  const std::vector<render::Camera> one = {scene.request.scene.camera};
  render_frames(scene, one, progress, [&](int64_t, const RenderedImages& images) {
    for (const render::AuxPass pass : separate_passes(s, image.format)) {
      Output out(pass_file(*file, pass).string());
      out.write(encode_pass(images, pass, image));
      out.finish();
    }
    Output out(file);
    out.write(encode_picture(images, image));
    out.finish();
  });
}

}  // namespace

Command render_command() {
  return {"render",
          kSynopsis,
          "path-trace a scene (the JSON body of POST /api/v1/renders) or a framed model to an image or a "
          "turntable",
          {"quiet", kGroundSwitch, kDenoiseSwitch, kNoDenoiseSwitch},
          help,
          run};
}

}  // namespace lp::cli
