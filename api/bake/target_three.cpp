// The three.js target: what three.js r187 documents for image-based lighting, an equirectangular map that
// PMREMGenerator.fromEquirectangular (or scene.environment with EquirectangularReflectionMapping)
// prefilters at run time, GGX level by level. Two files of the same map: NAME.hdr (Radiance RGBE, for
// HDRLoader) and NAME.jpg (Ultra HDR gain-map JPEG, for UltraHDRLoader: a tenth of the size, and an SDR
// picture in any viewer). No prefiltered chain: PMREM makes its own.
#include <fmt/format.h>

#include "api/bake/bake_manifest.hpp"
#include "api/bake/targets.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/latlong_resample.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ultrahdr.hpp"

namespace lp::api {
namespace {

// three.js looks an equirectangular texture up at u = atan2(e.z, e.x) / 2 pi + 1/2 of the engine
// direction e, v = asin(e.y) / pi + 1/2 (the top row up, its loaders flip rows). With e = (x, z, -y) of
// the world direction that is u = 1/2 - (the map's u), rows unchanged: the map mirrored left to right
// about u = 1/4. For an even width that moves whole columns: column c goes to W/2 - 1 - c (mod W).
Image three_latlong(const Image& map) {
  const Image even = map.width() % 2 == 0 ? map : resample_latlong(map, map.width() + 1, map.height());
  const int w = even.width();
  Image out(w, even.height());
  for (int y = 0; y < even.height(); ++y)
    for (int x = 0; x < w; ++x) out.set(((w / 2 - 1 - x) % w + w) % w, y, even.at(x, y));
  return out;
}

Json three_manifest(const BakeInput& input, const std::string& hdr, const std::string& jpg,
                    const ultrahdr::GainMapParams& gain) {
  Json m = manifest_common(input, BakeTarget::Three);
  m["face_order"] = "none: one equirectangular (lat-long) image, three.js's EquirectangularReflectionMapping";
  m["projection"] = {
      {"text",
       "three.js's equirectangular: column u = atan2(e.z, e.x) / 2 pi + 1/2 and row v = asin(e.y) / pi + 1/2 "
       "of "
       "the engine direction e (top row up), i.e. this map's lat-long mirrored about u = 1/4 so that a "
       "direction of the world lands where three.js looks for its engine direction"},
      {"mapping", "EquirectangularReflectionMapping"}};
  m["roughness_to_lod"] = {
      {"text",
       "none baked: three.js's PMREMGenerator prefilters the map at run time (GGX, visible-normal sampling "
       "for its sharp levels) and MeshStandardMaterial.roughness picks its level "
       "(PMREMGenerator.lodToRoughness)"},
      {"prefiltered", false}};
  m["files"] = Json::array(
      {{{"name", hdr},
        {"content", "the map as Radiance RGBE (linear radiance, shared 8-bit exponent: 1% steps)"},
        {"loader", "HDRLoader (three/addons/loaders/HDRLoader.js)"}},
       {{"name", jpg},
        {"content",
         "the map as an Ultra HDR JPEG: SDR base = radiance clipped at 1, sRGB; per-channel gain map of log2 "
         "HDR / SDR over [GainMapMin, GainMapMax] in 8 bits, hdrgm XMP and MPF index"},
        {"loader", "UltraHDRLoader (three/addons/loaders/UltraHDRLoader.js)"},
        {"gain_map",
         {{"gain_map_min", gain.gain_map_min},
          {"gain_map_max", gain.gain_map_max},
          {"gamma", gain.gamma},
          {"offset_sdr", gain.offset_sdr},
          {"offset_hdr", gain.offset_hdr},
          {"hdr_capacity_min", gain.hdr_capacity_min},
          {"hdr_capacity_max", gain.hdr_capacity_max}}},
        {"precision",
         "three.js r187's loader applies the gain to sRGB-encoded values with a weight 0.5 log2 1.8 that "
         "approximates the specification's linear gain: exact where the gain is 0 (radiance within [0, 1]), "
         "within about 5% above; it stores half floats, so radiance over 65504 is clipped there"}}});
  m["import"] = {
      {"three_revision", "r187"},
      {"code",
       fmt::format(
           "const texture = await new HDRLoader().loadAsync('{}'); // or new UltraHDRLoader() with '{}'\n"
           "texture.mapping = THREE.EquirectangularReflectionMapping;\n"
           "scene.environment = texture; // or new THREE.PMREMGenerator(renderer)"
           ".fromEquirectangular(texture).texture",
           hdr, jpg)},
      {"units", "the radiance as in the map: renderer.toneMapping and exposure apply on top"}};
  return m;
}

std::vector<BakeFile> write_three(const BakeInput& input) {
  const Image map = three_latlong(input.map.image());
  const std::string hdr = input.name + ".hdr", jpg = input.name + ".jpg";
  std::vector<uint8_t> ultrahdr = encode_ultrahdr(map);
  const auto gain = ultrahdr::split(ultrahdr).params;
  std::vector<BakeFile> files{{hdr, "image/vnd.radiance", write_hdr(map)},
                              {jpg, "image/jpeg", std::move(ultrahdr)}};
  files.push_back(manifest_file(three_manifest(input, hdr, jpg, gain)));
  return files;
}

std::optional<PrefilterParams> no_chain(const PrefilterRequest&) {
  return std::nullopt;
}

}  // namespace

TargetSpec three_target() {
  return {BakeTarget::Three,
          "three.js r187: NAME.hdr and NAME.jpg (Ultra HDR) equirectangular maps in three.js's frame, for "
          "PMREMGenerator.fromEquirectangular at run time",
          no_chain, write_three};
}

}  // namespace lp::api
