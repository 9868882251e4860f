// The `filament` target: what Filament's cmgen deploys (`cmgen --format=ktx -x DIR MAP`) and Filament's
// IndirectLight and Skybox load: NAME_ibl.ktx, the prefiltered cube in R11F_G11F_B10F with the `sh`
// metadata, NAME_skybox.ktx, level 0 alone, and manifest.json.
#include <fmt/format.h>

#include <bit>

#include "api/api_error.hpp"
#include "api/bake/bake_manifest.hpp"
#include "api/bake/filament_sh.hpp"
#include "api/bake/targets.hpp"
#include "api/prefilter_request.hpp"
#include "engine/image/ktx1.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/projection/cube_face.hpp"

namespace lp::api {
namespace {

// cmgen's chain: faces of --size (256 by default, a power of two) down to 16 texels (its
// --ibl-min-lod-size), or to 1 when --size is 16 or less.
constexpr int kSmallestLevel = 16;

int cmgen_levels(int base_size) {
  const int base_exponent = std::countr_zero(unsigned(base_size));
  const int smallest = std::countr_zero(unsigned(kSmallestLevel));
  return base_exponent + 1 - (smallest >= base_exponent ? 0 : smallest);
}

std::optional<PrefilterParams> chain_params(const PrefilterRequest& request) {
  PrefilterParams p;
  p.projection = Projection::Cube;
  p.level_roughness = LevelRoughness::Filament;
  p.base_size = request.params.base_size;
  p.samples = request.params.samples;
  if (!std::has_single_bit(unsigned(p.base_size)))
    throw invalid_field("base_size", fmt::format("the target 'filament' takes a power of two, as cmgen's "
                                                 "--size, got {}",
                                                 p.base_size));
  p.levels = cmgen_levels(p.base_size);
  return p;
}

Json level_roughness(const PrefilterParams& p) {
  Json levels = Json::array();
  for (int i = 0; i < p.levels; ++i) levels.push_back(p.roughness(i));
  return levels;
}

Json manifest(const BakeInput& input, const FilamentSh& sh, const std::string& ibl,
              const std::string& skybox) {
  const PrefilterParams& p = input.chain->params;
  Json m = manifest_common(input, BakeTarget::Filament);
  m["face_order"] = {{"text",
                      "each level's faces +X, -X, +Y, -Y, +Z, -Z of the engine frame, oriented as OpenGL's "
                      "cube map table (rows from t = 0): Filament samples the cube with the engine-frame "
                      "direction as written, no mirroring"},
                     {"faces", {"px", "nx", "py", "ny", "pz", "nz"}}};
  m["roughness_to_lod"] = {
      {"text", fmt::format("Filament's lod = (levels - 1) r (2 - r) with r the perceptual "
                           "roughness (IndirectLight reads levels - 1 = {} from the "
                           "texture): {}",
                           p.levels - 1, level_roughness_formula(p.level_roughness))},
      {"levels", p.levels},
      {"roughness", level_roughness(p)}};
  m["files"] = {{{"name", ibl},
                 {"role",
                  "IndirectLight reflections: the prefiltered cube, KTX 1.1 GL_R11F_G11F_B10F, "
                  "its `sh` metadata the irradiance"}},
                {{"name", skybox}, {"role", "Skybox: level 0 alone, KTX 1.1 GL_R11F_G11F_B10F"}}};
  m["import"] = {
      {"text",
       "as cmgen's deployment: IndirectLight.Builder().reflections(ibl texture).irradiance(3, sh) (JS: "
       "engine.createIblFromKtx1); Skybox from the skybox file (engine.createSkyFromKtx1). The map as "
       "the product reads it (z-up lat-long); cmgen reads a lat-long file mirrored and turned, its "
       "direction (x, y, z) in the engine frame being the product's (-z, y, -x)"},
      {"sh",
       {{"text",
         "cmgen's: E(n) / pi of a white Lambertian surface as the polynomial Filament's shader sums, terms "
         "1, "
         "y, z, x, yx, yz, 3z^2 - 1, zx, x^2 - y^2 of the engine-frame normal, bands windowed by sinc(pi l / "
         "w)^4 as cmgen's --sh-window=auto"},
        {"window_cutoff", sh.window_cutoff},
        {"coefficients", sh.coefficients}}}};
  return m;
}

std::vector<BakeFile> write(const BakeInput& input) {
  const PrefilteredChain& chain = *input.chain;
  const FilamentSh sh = filament_sh(input.sh);
  const std::string ibl = input.name + "_ibl.ktx", skybox = input.name + "_skybox.ktx";
  std::vector<BakeFile> files;
  files.push_back({ibl, "image/ktx", write_ktx1_cube(chain.levels, {{"sh", filament_sh_text(sh)}})});
  files.push_back({skybox, "image/ktx", write_ktx1_cube(std::span(chain.levels).first(1))});
  files.push_back(manifest_file(manifest(input, sh, ibl, skybox)));
  return files;
}

}  // namespace

TargetSpec filament_target() {
  return {
      BakeTarget::Filament,
      "Filament: NAME_ibl.ktx (KTX1 R11F_G11F_B10F prefiltered cube with cmgen's sh) and NAME_skybox.ktx, as "
      "cmgen deploys them",
      chain_params, write};
}

}  // namespace lp::api
