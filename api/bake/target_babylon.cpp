// The `babylon` target: NAME.env, Babylon.js's prefiltered environment (api/bake/babylon_env_chain.hpp),
// loaded with CubeTexture.CreateFromPrefilteredData as a scene's environmentTexture.
#include <bit>
#include <string>

#include "api/api_error.hpp"
#include "api/bake/babylon_env_chain.hpp"
#include "api/bake/bake_manifest.hpp"
#include "api/bake/targets.hpp"
#include "api/prefilter_request.hpp"
#include "engine/image/babylon_env.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {
namespace {

std::optional<PrefilterParams> babylon_chain(const PrefilterRequest& request) {
  PrefilterParams p = request.params;
  if (!std::has_single_bit(unsigned(p.base_size)))
    throw invalid_field("base_size", "must be a power of two for the target 'babylon' (Babylon's .env)");
  p.projection = Projection::Cube;
  p.level_roughness = LevelRoughness::Babylon;
  p.levels = prefilter_max_levels(Projection::Cube, p.base_size);  // .env holds the full pyramid
  return p;
}

Json frame() {
  return {{"text",
           "the world is z up (the map's lat-long frame); Babylon's scenes are left-handed, y up: world "
           "direction "
           "(x, y, z) is Babylon (-x, z, -y), where Babylon's glTF loader puts a glTF asset that our renders "
           "place as the glTF importer of Blender does (glTF (x, y, z) is Babylon (-x, y, z), world (x, -z, "
           "y)), so a model and the map keep their places; Babylon's +Y is the zenith"},
          {"world_to_engine", kWorldToBabylon}};
}

Json roughness_to_lod(const PrefilterParams& p) {
  Json levels = Json::array();
  for (int i = 0; i < p.levels; ++i)
    levels.push_back({{"level", i}, {"size", prefilter_level_size(p, i)}, {"roughness", p.roughness(i)}});
  return {{"text",
           "Babylon's PBR materials sample lod = lodGenerationScale log2(size alpha), alpha = roughness^2 + "
           "0.0005 (lodGenerationOffset 0), between levels trilinearly; level i is filtered as Babylon's "
           "HDRFiltering does: " +
               std::string(level_roughness_formula(p.level_roughness))},
          {"lod_generation_scale", kBabylonLodGenerationScale},
          {"levels", levels}};
}

std::vector<BakeFile> write_babylon(const BakeInput& input) {
  const PrefilterParams& p = input.chain->params;
  const std::string env_name = input.name + ".env";
  Json m = manifest_common(input, BakeTarget::Babylon);
  m["frame"] = frame();
  m["units"]["encoding"] =
      "RGBD in 8-bit PNG as Babylon's rgbdEncode writes it: radiance = rgb^2.2 / D with D in alpha, up to "
      "255 "
      "(brighter saturates), 8 bits after the 2.2 curve";
  m["face_order"] = {
      {"text",
       "the .env's order: level 0 first, in each level the faces +X, -X, +Y, -Y, +Z, -Z of Babylon's frame "
       "as "
       "OpenGL's cube map table lays them; each image is stored bottom row first, as Babylon uploads it"},
      {"faces", {"px", "nx", "py", "ny", "pz", "nz"}}};
  m["roughness_to_lod"] = roughness_to_lod(p);
  m["irradiance"] =
      "the .env's spherical polynomial (SphericalPolynomial.FromHarmonics of E / pi of the SH above, in "
      "Babylon's frame); PBR materials evaluate it as harmonics (brdf.useSphericalHarmonics, the default)";
  m["import"] = {{"babylon", "scene.environmentTexture = CubeTexture.CreateFromPrefilteredData('" + env_name +
                                 "', scene)"},
                 {"size", p.base_size},
                 {"image_type", "image/png"}};
  m["files"] =
      Json::array({{{"name", env_name},
                    {"content_type", "application/octet-stream"},
                    {"what", "Babylon .env version 2: the prefiltered cube and the irradiance"}},
                   {{"name", kManifestFile}, {"content_type", "application/json"}, {"what", "this"}}});
  std::vector<BakeFile> files;
  files.push_back({env_name, "application/octet-stream", babylon_env_file(*input.chain, input.sh)});
  files.push_back(manifest_file(m));
  return files;
}

}  // namespace

TargetSpec babylon_target() {
  return {BakeTarget::Babylon,
          "Babylon.js: NAME.env (version 2: RGBD PNG cube levels on Babylon's lod scale, the irradiance "
          "polynomial)",
          babylon_chain, write_babylon};
}

}  // namespace lp::api
