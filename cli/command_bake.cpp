// lightprobe bake MAP --out DIR: everything a real-time engine needs of a map, in one folder: the SH JSON
// (`lightprobe sh`'s answer with its defaults), the prefiltered chain (the files of POST
// /api/v1/envmaps/{id}/prefilter, its options the request's fields), the DFG table (`lightprobe
// brdf-lut`'s EXR with its defaults) and manifest.json, which lists every file with its conventions.
// With --target NAME: the files one engine loads instead (api/bake: the target's chain, then its files).
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "api/bake/bake_manifest.hpp"
#include "api/bake/bake_request.hpp"
#include "api/brdf_lut_request.hpp"
#include "api/prefilter_files.hpp"
#include "api/prefilter_request.hpp"
#include "api/prefilter_schema.hpp"
#include "api/sh_request.hpp"
#include "api/sh_schema.hpp"
#include "cli/command.hpp"
#include "cli/help.hpp"
#include "cli/map_argument.hpp"
#include "cli/output.hpp"
#include "cli/progress_bar.hpp"
#include "engine/core/error.hpp"
#include "engine/core/limits.hpp"
#include "engine/ibl/dfg_lut.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::cli {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr std::string_view kSynopsis = "bake MAP --out DIR [--target NAME] [options]";
constexpr const char* kShFile = "sh.json";
constexpr const char* kLutFile = "brdf_lut.exr";
using api::kManifestFile;

// "  gltf  summary" lines of the available targets.
std::string target_lines() {
  std::string out;
  for (const api::BakeTarget t : api::available_targets())
    out += fmt::format("    {:<10}{}\n", enum_name(t), api::target_spec(t).summary);
  return out;
}

std::string help() {
  const api::PrefilterRequest d;
  const auto range = [](const Range<int>& r, int fallback) {
    return fmt::format("in [{}, {}] (default {})", r.min, r.max, fallback);
  };
  return fmt::format(
             "Writes into DIR (made if missing) the bundle of image-based lighting: {} (`lightprobe sh`'s\n"
             "answer: {} bands with the irradiance), the prefiltered GGX chain (the files of POST\n"
             "/api/v1/envmaps/{{id}}/prefilter), {} (`lightprobe brdf-lut`'s table, {} texels a side) and\n"
             "{}, every file with its conventions. Progress on standard error.\n\n",
             kShFile, api::kDefaultShBands, kLutFile, api::kDefaultDfgLutSize, kManifestFile) +
         option_line("--out DIR", "the folder to write (required)") +
         option_line("--target NAME", "the files one engine loads instead of the bundle (one of: " +
                                          api::available_target_names() +
                                          "); the target fixes some options") +
         target_lines() + option_line("--projection NAME", choices(d.params.projection)) +
         option_line("--level-roughness NAME",
                     choices(d.params.level_roughness) + ": each level's roughness") +
         option_line("--format NAME", choices(d.format) + ": one EXR a level, or one KTX2 file") +
         option_line("--precision NAME", choices(d.precision)) +
         option_line("--levels N", "mip levels, " + range(limits::kPrefilterLevels, d.params.levels)) +
         option_line("--base-size N", "level 0's size in the projection's terms, " +
                                          range(limits::kPrefilterBaseSize, d.params.base_size)) +
         option_line("--samples N",
                     "GGX samples a texel, " + range(limits::kPrefilterSamples, d.params.samples)) +
         invalid_pixel_policy_help() + option_line("-q, --quiet", "no progress");
}

void write_file(const fs::path& dir, const std::string& name, std::span<const uint8_t> bytes) {
  Output out((dir / name).string());
  out.write(bytes);
  out.finish();
}

void write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  write_file(dir, name, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

void make_folder(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir))
    throw Error(ErrorKind::WriteFailed, fmt::format("cannot make the folder '{}': {}", dir.string(),
                                                    error ? error.message() : "a file is in the way"));
}

// `lightprobe sh MAP`'s answer.
json bake_sh(const EnvMap& map, const fs::path& dir) {
  const auto start = std::chrono::steady_clock::now();
  const ShCoefficients coefficients = project_sh(map.image());
  const double elapsed =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const std::string text = api::sh_json(coefficients, api::parse_sh_query({}), elapsed, false);
  write_file(dir, kShFile, text + "\n");
  return {{"name", kShFile},
          {"content", "spherical harmonics of the radiance, the irradiance and the Lambertian coefficients"},
          {"convention", json::parse(text)["convention"]}};
}

PrefilteredChain prefilter(const EnvMap& map, const PrefilterParams& params, ProgressStyle progress) {
  ProgressBar bar("bake", prefilter_work_units(params), progress);
  auto chain = prefilter_chain(map, params, {nullptr, [&bar](int64_t units) { bar.advance(units); }});
  bar.finish();
  return std::move(*chain);
}

json bake_chain(const LoadedMap& loaded, const api::PrefilterRequest& request, const fs::path& dir,
                ProgressStyle progress) {
  const PrefilteredChain chain = prefilter(*loaded.map, request.params, progress);
  json description;
  api::describe_prefilter(description, request, {loaded.name, ".", true, chain.source_width});
  json files = json::array();
  for (const std::string& name : api::prefilter_file_names(request)) {
    write_file(dir, name, api::encode_prefilter_file(chain, request, name));
    files.push_back(name);
  }
  description["files"] = files;
  description.erase("files_available");
  description["content"] = "the GGX-prefiltered specular chain of the radiance";
  return description;
}

json bake_lut(const fs::path& dir) {
  const api::BrdfLutRequest r = api::parse_brdf_lut_query({});
  write_file(dir, kLutFile,
             write_image(api::dfg_lut_image(make_dfg_lut(r.size, r.multiscatter)), ImageFormat::Exr,
                         api::kLinearPng));
  return {{"name", kLutFile},
          {"content", "the split-sum DFG table of GGX (GET /api/v1/brdf-lut)"},
          {"size", r.size},
          {"convention",
           {{"layout",
             "texel (x, y) at n.v = (x + 0.5) / size and roughness (y + 0.5) / size, row 0 the "
             "smoothest"},
            {"roughness", "perceptual, GGX alpha = roughness^2, as the chain's"},
            {"channels",
             "red = scale, green = bias, blue 0: specular = prefiltered radiance (F0 scale + "
             "bias)"}}}};
}

// The target's chain, then its files.
void bake_target(const LoadedMap& loaded, const api::PrefilterRequest& request, const fs::path& dir,
                 ProgressStyle progress) {
  std::optional<PrefilteredChain> chain;
  if (api::makes_chain(request)) chain = prefilter(*loaded.map, request.params, progress);
  const ShCoefficients sh = project_sh(loaded.map->image(), api::kBakeShBands);
  const api::BakeInput input{loaded.name, *loaded.map, chain ? &*chain : nullptr, sh, request};
  for (const api::BakeFile& file : api::target_spec(*request.target).write(input))
    write_file(dir, file.name, file.bytes);
}

void run(Arguments& args) {
  args.expect_positional(1, kSynopsis);
  const fs::path dir(args.take_required("out", kSynopsis));
  const ProgressStyle progress = progress_style(args.take_switch("quiet"));
  const InvalidPixelPolicy policy = take_invalid_pixel_policy(args);
  const api::PrefilterRequest request = api::parse_prefilter_request(args.take_rest_as_json().dump());
  const LoadedMap loaded = load_map(args.positional()[0], policy);
  make_folder(dir);
  if (request.target) return bake_target(loaded, request, dir, progress);
  const json sh = bake_sh(*loaded.map, dir);
  const json chain = bake_chain(loaded, request, dir, progress);
  const json manifest = {
      {"map", {{"name", loaded.name}, {"source", loaded.source}, {"format", loaded.format}}},
      {"frame", chain["convention"]["frame"]},
      {"sh", sh},
      {"prefiltered", chain},
      {"brdf_lut", bake_lut(dir)}};
  write_file(dir, kManifestFile, manifest.dump(2) + "\n");
}

}  // namespace

Command bake_command() {
  return {"bake",
          kSynopsis,
          "the bundle of image-based lighting: SH, prefiltered chain, DFG table and a manifest",
          {"quiet"},
          help,
          run};
}

}  // namespace lp::cli
