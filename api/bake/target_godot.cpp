// Godot 4: the map as the panorama PanoramaSkyMaterial samples (NAME_panorama.exr), level 0 of the cube
// as the six faces Godot's Cubemap import slices (NAME_cubemap.exr, arrangement 6x1), and the prefiltered
// cube chain as ASTC HDR in KTX 2.0 (NAME_radiance_astc.ktx2) for a renderer sampling it itself.
#include <fmt/format.h>

#include "api/bake/desktop_files.hpp"
#include "api/bake/targets.hpp"
#include "api/prefilter_request.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {
namespace {

// Godot's sky shader: u = atan(d.x, -d.z) / 2 pi, so u = 1/4 - ours (its u = 0 is -Z, the world's +y).
constexpr PanoramaColumns kPanorama{-1, 0.25};

EngineFrame godot_frame() {
  return {
      world_to_engine(),
      "Godot is y up, right-handed, -Z forward, glTF's axes (its glTF import keeps them): world (x, y, z) "
      "is Godot (x, z, -y); Godot's +Y is the world's zenith, its forward -Z the world's +y",
      "Godot's Cubemap class reference (docs.godotengine.org/en/stable/classes/class_cubemap.html: image "
      "order X+, X-, Y+, Y-, Z+, Z-, Y+ up, Z- forward); Godot's sky shader "
      "(servers/rendering/renderer_rd/shaders/environment/sky.glsl: panorama u = atan(d.x, -d.z) / 2 pi "
      "wrapped to [0, 1), v = acos(d.y) / pi from the top row)"};
}

Json import_json(const std::string& panorama, const std::string& cubemap, const std::string& ktx2) {
  return {{"panorama",
           {{"file", panorama},
            {"Import As", "Texture2D"},
            {"compress/mode", "VRAM Compressed"},
            {"mipmaps/generate", true},
            {"use",
             "WorldEnvironment > Environment: Background Mode Sky; Sky > Sky Material a PanoramaSkyMaterial "
             "with Panorama this texture; Ambient Light and Reflected Light Source Sky (Godot prefilters the "
             "sky's radiance itself, Sky > Radiance Size)"}}},
          {"cubemap",
           {{"file", cubemap},
            {"Import As", "Cubemap"},
            {"slices/arrangement", "6x1"},
            {"compress/mode", "VRAM Compressed"},
            {"mipmaps/generate", true},
            {"use",
             "a sky ShaderMaterial sampling it as samplerCube with EYEDIR (the shader of Godot's Cubemap "
             "class reference), e.g. for a ReflectionProbe-free sky"}}},
          {"astc_cube",
           {{"file", ktx2},
            {"reader",
             "a Vulkan or OpenGL ES renderer with ASTC HDR (VK_EXT_texture_compression_astc_hdr, "
             "KHR_texture_compression_astc_hdr) through libktx; Godot's own import compresses the EXRs "
             "above instead (compress/mode VRAM Compressed: ASTC on mobile with "
             "rendering/textures/vram_compression/import_etc2_astc)"}}}};
}

std::vector<BakeFile> write(const BakeInput& input) {
  std::vector<BakeFile> files;
  files.push_back(exr_file(input.name + "_panorama.exr", panorama_columns(input.map.image(), kPanorama),
                           ExrEnvmap::LatLong, input));
  files.push_back(exr_file(input.name + "_cubemap.exr", input.chain->levels[0], ExrEnvmap::None, input));
  files.push_back(astc_cube_file(input.name + "_radiance_astc.ktx2", input, false));

  add_manifest(
      files, input, BakeTarget::Godot,
      {godot_frame(),
       "NAME_cubemap.exr: six N x N faces side by side, X+, X-, Y+, Y-, Z+, Z- in Godot's axes, each "
       "oriented as the OpenGL/Vulkan cube-map table (row 0 at the top); the KTX2's faces likewise",
       chain_roughness_json(*input.chain),
       import_json(files[0].name, files[1].name, files[2].name),
       {"lat-long panorama for PanoramaSkyMaterial", "cube level 0 for the Cubemap import",
        "prefiltered GGX cube chain, ASTC 4x4 HDR"}});
  return files;
}

}  // namespace

TargetSpec godot_target() {
  return {BakeTarget::Godot,
          "Godot 4: an EXR panorama for PanoramaSkyMaterial, a 6x1 EXR cube for the Cubemap import, and the "
          "prefiltered cube chain as ASTC HDR KTX2",
          astc_cube_chain_params, write};
}

}  // namespace lp::api
