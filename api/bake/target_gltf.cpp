// The gltf target: NAME.gltf, a glTF 2.0 scene holding only its environment light, as
// KHR_lights_environment (draft) declares it: the radiance as a KTX2 cube (RGBA16F, the full pyramid of
// mip levels down to 1 x 1 faces, prefiltered with lod = roughness (levels - 1)) and the 9 x 3 irradiance
// coefficients, in glTF's y-up frame; and the same chain as EXT_lights_image_based (gltf_image_based.hpp).
#include <fmt/format.h>

#include <cmath>

#include "api/api_error.hpp"
#include "api/bake/bake_manifest.hpp"
#include "api/bake/gltf_image_based.hpp"
#include "api/bake/targets.hpp"
#include "api/prefilter_files.hpp"
#include "api/prefilter_request.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/sh/sh_rotation.hpp"

namespace lp::api {
namespace {

constexpr const char* kExtension = "KHR_lights_environment";

std::optional<PrefilterParams> gltf_chain(const PrefilterRequest& request) {
  if (request.precision != PixelPrecision::Half)
    throw invalid_field("precision", "the target 'gltf' writes RGBA16F cubes: 'half' only");
  const int size = request.params.base_size;
  if ((size & (size - 1)) != 0)
    throw invalid_field("base_size", fmt::format("the target 'gltf' needs a power of two, got {}", size));
  PrefilterParams p = request.params;
  p.projection = Projection::Cube;
  p.level_roughness = LevelRoughness::Linear;
  p.levels = prefilter_max_levels(Projection::Cube, size);
  return p;
}

// The 9 x 3 irradiance coefficients E_lm = A_l L_lm in glTF's frame.
Json irradiance_coefficients(const ShCoefficients& radiance) {
  const ShCoefficients e = rotate_sh(sh_irradiance(radiance), world_to_engine());
  Json out = Json::array();
  for (const ShRgb& c : e.rgb) out.push_back({c[0], c[1], c[2]});
  return out;
}

// The document and, appended to `files`, the PNG faces of EXT_lights_image_based.
Json gltf_document(const BakeInput& in, const std::string& stem, const std::string& cube_file,
                   std::vector<BakeFile>& files) {
  const Json light = {
      {"name", in.name}, {"irradianceCoefficients", irradiance_coefficients(in.sh)}, {"cubemap", 0}};
  Json images = {{{"name", in.name + " radiance cube"}, {"uri", cube_file}, {"mimeType", "image/ktx2"}}};
  const Json image_based = image_based_light(in, stem, images, files);
  return {{"asset", {{"version", "2.0"}, {"generator", "lightprobe bake --target gltf"}}},
          {"extensionsUsed", {kExtension, kImageBasedExtension}},
          {"extensions",
           {{kExtension, {{"cubemaps", {{{"source", 0}, {"layer", 0}}}}, {"lights", {light}}}},
            {kImageBasedExtension, {{"lights", {image_based}}}}}},
          {"images", images},
          {"scene", 0},
          {"scenes",
           {{{"name", in.name},
             {"extensions", {{kExtension, {{"light", 0}}}, {kImageBasedExtension, {{"light", 0}}}}}}}}};
}

std::vector<uint8_t> cube_ktx2(const BakeInput& in) {
  PrefilterRequest request = in.request;
  request.target.reset();
  request.format = PrefilterFormat::Ktx2;
  return encode_prefilter_file(*in.chain, request, prefilter_file_names(request).front());
}

Json roughness_to_lod(const PrefilterParams& p) {
  Json levels = Json::array();
  for (int i = 0; i < p.levels; ++i) levels.push_back(p.roughness(i));
  return {{"text", "lod = roughness (levels - 1), KHR_lights_environment's; " +
                       std::string(level_roughness_formula(p.level_roughness))},
          {"levels", p.levels},
          {"roughness", levels}};
}

std::vector<BakeFile> write_gltf(const BakeInput& in) {
  const std::string stem = bake_file_stem(in.name);
  const std::string gltf_file = stem + ".gltf", cube_file = stem + "_radiance.ktx2";
  std::vector<BakeFile> faces;
  const std::string gltf = gltf_document(in, stem, cube_file, faces).dump(2) + "\n";
  std::vector<BakeFile> files;
  files.push_back({gltf_file, "model/gltf+json", {gltf.begin(), gltf.end()}});
  files.push_back({cube_file, "image/ktx2", cube_ktx2(in)});
  for (BakeFile& f : faces) files.push_back(std::move(f));
  Json manifest = manifest_common(in, BakeTarget::Gltf);
  manifest["face_order"] =
      "KTX2 cube faces +X, -X, +Y, -Y, +Z, -Z of glTF's frame, each oriented as OpenGL's cube map table "
      "(the KTX2 specification's)";
  manifest["roughness_to_lod"] = roughness_to_lod(in.chain->params);
  manifest["irradiance_coefficients"] =
      "KHR_lights_environment's irradianceCoefficients: E_lm = A_l L_lm (the irradiance of sh, Ramamoorthi "
      "and Hanrahan 2001) in glTF's frame, in sh.convention's basis and order, each [r, g, b]";
  manifest["image_based"] = {
      {"extension", kImageBasedExtension},
      {"faces",
       "specularImages[level] lists the faces +X, -X, +Y, -Y, +Z, -Z of the cube map table (OpenGL's, "
       "left-handed) in Babylon.js's scene frame (glTF with x mirrored, as its glTF loader places a model), "
       "each image flipped for glTF's texture space: the KTX2 face of the opposite x sign for +X and -X, "
       "every face turned by 180 degrees; RGBD 8-bit PNGs (RGB = (colour D)^(1/2.2), A = D)"},
      {"levels",
       "the KTX2 cube's levels, level i at roughness i / (levels - 1) (linear, as the extension states); "
       "Babylon.js's loader sets lodGenerationScale = (levels - 1) / log2(specularImageSize) and its PBR "
       "materials read lod = lodGenerationScale log2(specularImageSize alpha), alpha = roughness^2 (its "
       "getLodFromAlphaG), which is not linear in roughness"},
      {"irradiance_coefficients",
       "E_lm = A_l L_lm (irradiance, not radiance: Babylon.js's loader divides by pi to get the Lambertian "
       "radiance) in Babylon.js's scene frame and basis: sh.convention's basis with the Condon-Shortley "
       "sign on m = -1 and m = 1, in sh.convention's order, each [r, g, b]"},
      {"rotation", "identity: the faces and coefficients are written in the frame the loader uses"},
      {"intensity", "1, written out: Babylon.js's loader scales the coefficients by it and has no default"}};
  manifest["import"] = {
      {"extension", kExtension},
      {"gltf", gltf_file},
      {"layout", "the draft's root cubemaps (image, layer) and lights; scenes[0] names light 0"}};
  Json names = Json::array();
  for (const BakeFile& f : files) names.push_back(f.name);
  names.push_back(kManifestFile);
  manifest["files"] = names;
  files.push_back(manifest_file(manifest));
  return files;
}

}  // namespace

TargetSpec gltf_target() {
  return {BakeTarget::Gltf,
          "glTF 2.0 with KHR_lights_environment (a KTX2 RGBA16F cube with its full prefiltered pyramid and "
          "the 9 x 3 irradiance SH) and EXT_lights_image_based (the same levels as RGBD PNG faces)",
          gltf_chain, write_gltf};
}

}  // namespace lp::api
