// Unity: the map as a lat-long EXR that Unity's texture importer turns into a cube map (Texture Shape
// Cube, Mapping Latitude-Longitude Layout, Convolution Type Specular), laid out in Unity's left-handed
// frame; and the prefiltered cube chain as ASTC HDR in KTX 2.0 in the same frame.
#include "api/bake/desktop_files.hpp"
#include "api/bake/targets.hpp"
#include "api/prefilter_request.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {
namespace {

// Unity's panoramic mapping: u = 0.5 - atan2(d.z, d.x) / 2 pi in Unity's axes, which is minus ours.
constexpr PanoramaColumns kPanorama{-1, 0.0};

EngineFrame unity_frame() {
  return {
      {{{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}},
      "Unity is y up, left-handed, +Z forward; its glTF importers (glTFast, UnityGLTF) negate glTF's x, so "
      "world (x, y, z) is Unity (-x, z, -y): Unity's +Y is the world's zenith, its forward +Z the world's -y "
      "(the side a glTF model's front faces), its right +X the world's -x",
      "Unity Manual, Cubemap texture Import Settings (docs.unity3d.com/Manual/texture-type-cubemap.html: "
      "Mapping, Convolution Type, Fixup Edge Seams); Unity's built-in Skybox/Panoramic shader "
      "(ToRadialCoords: uv = (0.5 - atan2(d.z, d.x) / 2 pi, 1 - acos(d.y) / pi)), the lat-long mapping "
      "this file is laid out for; glTFast's conversion of glTF's right-handed axes by negating x"};
}

Json import_json(const std::string& latlong, const std::string& ktx2) {
  return {{"file", latlong},
          {"Texture Type", "Default"},
          {"Texture Shape", "Cube"},
          {"Mapping", "Latitude-Longitude Layout (Cylindrical)"},
          {"Convolution Type", "Specular (Glossy Reflection)"},
          {"Fixup Edge Seams", true},
          {"sRGB (Color Texture)", false},
          {"Generate Mipmaps", true},
          {"Format",
           {{"Standalone", "BC6H (TextureImporterFormat.BC6H)"},
            {"Android, iOS", "ASTC HDR 4x4 (TextureImporterFormat.ASTC_HDR_4x4)"}}},
          {"TextureImporter",
           {{"textureShape", "TextureImporterShape.TextureCube"},
            {"generateCubemap", "TextureImporterGenerateCubemap.Cylindrical"},
            {"cubemapConvolution", "TextureImporterCubemapConvolution.Specular"},
            {"seamlessCubemap", true},
            {"sRGBTexture", false},
            {"mipmapEnabled", true}}},
          {"use",
           "Lighting window > Environment: Skybox Material a material of shader Skybox/Cubemap with "
           "this cube map as Cubemap (HDR); Environment Reflections: Source Custom, Cubemap this "
           "texture (or a Reflection Probe of Type Custom); Unity prefilters it on import (Convolution "
           "Type Specular) into its mip levels"},
          {"labels", "Unity 6's manual names the mapping \"Latitude Longitude (Cylindrical)\""},
          {"astc_cube",
           {{"file", ktx2},
            {"reader",
             "a Vulkan or OpenGL ES renderer with ASTC HDR (VK_EXT_texture_compression_astc_hdr) "
             "through libktx, in Unity's axes; Unity's own importer compresses the EXR above "
             "instead (Format ASTC HDR 4x4 on Android and iOS)"}}}};
}

std::vector<BakeFile> write(const BakeInput& input) {
  std::vector<BakeFile> files;
  files.push_back(exr_file(input.name + "_latlong.exr", panorama_columns(input.map.image(), kPanorama),
                           ExrEnvmap::LatLong, input));
  files.push_back(astc_cube_file(input.name + "_radiance_astc.ktx2", input, true));

  add_manifest(
      files, input, BakeTarget::Unity,
      {unity_frame(),
       "the KTX2's faces +X, -X, +Y, -Y, +Z, -Z in Unity's axes, each oriented as the OpenGL/Vulkan cube-map "
       "table (row 0 at the top); the EXR is one lat-long panorama, row 0 Unity's +Y",
       chain_roughness_json(*input.chain),
       import_json(files[0].name, files[1].name),
       {"lat-long panorama for the texture importer's cube map",
        "prefiltered GGX cube chain, ASTC 4x4 HDR"}});
  return files;
}

}  // namespace

TargetSpec unity_target() {
  return {BakeTarget::Unity,
          "Unity: a lat-long EXR for the texture importer's cube map (Latitude-Longitude Layout, Specular "
          "convolution) in Unity's left-handed frame, and the prefiltered cube chain as ASTC HDR KTX2",
          astc_cube_chain_params, write};
}

}  // namespace lp::api
