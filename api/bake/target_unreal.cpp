// Unreal Engine: the map as a Radiance HDR lat-long that Unreal imports as a TextureCube (the HDRI
// Backdrop's Cubemap, a Sky Light's Specified Cubemap), laid out in Unreal's left-handed z-up frame so
// that it needs no rotation. Unreal prefilters the cube itself, so no chain is shipped.
#include "api/bake/desktop_files.hpp"
#include "api/bake/targets.hpp"
#include "engine/envmap/envmap.hpp"

namespace lp::api {
namespace {

// Unreal's long-lat import: u = (1 + atan2(x, y) / pi) / 2 over Unreal's (x, y), which is 3/4 - ours.
constexpr PanoramaColumns kPanorama{-1, 0.75};

EngineFrame unreal_frame() {
  return {{{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}},
          "Unreal is z up, left-handed, +X forward, +Y right, in centimetres; world (x, y, z) is Unreal "
          "(x, -y, z), as Unreal's FBX import places a right-handed z-up scene: Unreal's +Z is the world's "
          "zenith, its forward +X the world's +x. The panorama is laid out so that it needs no rotation "
          "(Sky Light Source Cubemap Angle 0, HDRI Backdrop rotation 0); directions carry no length, so "
          "centimetres do not enter",
          "Unreal Engine's long-lat cube import (Runtime/Engine TextureCompressorModule: "
          "TransformSideToWorldSpace "
          "then DirectionToLongLat, u = (1 + atan2(d.x, -d.z) / pi) / 2 of the face direction with y and z "
          "exchanged), read in a public port of it; Unreal's coordinate system (X forward, Y right, Z up, "
          "left-handed)"};
}

Json import_json(const std::string& hdr) {
  return {{"file", hdr},
          {"Texture",
           {{"imported as", "TextureCube (Unreal imports a 2:1 .hdr as a long-lat cube map)"},
            {"Compression Settings", "HDR (RGBA16F, no sRGB)"},
            {"LOD Group", "Skybox"},
            {"sRGB", false},
            {"Mip Gen Settings", "FromTextureGroup"}}},
          {"HDRI Backdrop", {{"Cubemap", hdr}, {"Rotation", "(0, 0, 0)"}, {"Intensity", 1.0}}},
          {"Sky Light",
           {{"Source Type", "SLS Specified Cubemap"},
            {"Cubemap", hdr},
            {"Source Cubemap Angle", 0.0},
            {"Intensity Scale", 1.0}}},
          {"use",
           "drop the HDRI Backdrop actor (plugin HDRIBackdrop) and set its Cubemap, or a Sky Light with "
           "Source Type SLS Specified Cubemap; Unreal filters the cube for its reflections itself"}};
}

std::vector<BakeFile> write(const BakeInput& input) {
  std::vector<BakeFile> files;
  files.push_back(hdr_file(input.name + "_latlong.hdr", panorama_columns(input.map.image(), kPanorama)));

  add_manifest(
      files, input, BakeTarget::Unreal,
      {unreal_frame(),
       "none: one lat-long panorama, row 0 Unreal's +Z, u = 3/4 its forward +X",
       {{"text", "none shipped: the engine prefilters the imported cube for its Sky Light and reflections"}},
       import_json(files[0].name),
       {"lat-long panorama, imported as a TextureCube"}});
  return files;
}

}  // namespace

TargetSpec unreal_target() {
  return {BakeTarget::Unreal,
          "Unreal Engine: a Radiance HDR lat-long imported as a TextureCube for the HDRI Backdrop or a Sky "
          "Light, in Unreal's left-handed z-up frame (no rotation needed)",
          [](const PrefilterRequest&) -> std::optional<PrefilterParams> { return std::nullopt; }, write};
}

}  // namespace lp::api
