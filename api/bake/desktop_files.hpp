#pragma once
// What the desktop targets (unity, unreal, godot) write alike: the map re-laid as an engine's panorama
// (EXR, and Radiance HDR where the engine's docs name it), a cube map's faces as one EXR, the
// prefiltered cube chain as ASTC HDR in KTX 2.0, and the manifest's entries for them and for the frame.
#include <string>

#include "api/bake/bake_manifest.hpp"
#include "api/bake/bake_target.hpp"
#include "api/bake/engine_layouts.hpp"
#include "engine/image/exr_standard_attributes.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

// The preset the targets compress ASTC HDR at: astcenc's fast one, half the medium one's time for at most
// 2.2 dB of PSNR on the committed maps (bench/README.md, ASTC HDR).
inline constexpr float kBakeAstcQuality = 10.0f;

// An engine's axes against the world: engine = world_to_engine * world, the text saying how they lie,
// and where each engine documents its convention.
struct EngineFrame {
  Matrix3 world_to_engine;
  const char* text;
  const char* sources;
};
Json frame_json(const EngineFrame& frame);

// `image` as an EXR of the request's precision with OpenEXR's `chromaticities` and `envmap` (LatLong for
// a panorama; None for a strip of cube faces, a layout OpenEXR does not define).
BakeFile exr_file(const std::string& name, const Image& image, ExrEnvmap envmap, const BakeInput& input);
BakeFile hdr_file(const std::string& name, const Image& image);
// The chain's cube levels (strips of faces in the cube frame of cube_face.hpp) as an ASTC 4x4 HDR KTX2
// cube, each level's faces x-mirrored first for a left-handed engine (cube_strip_x_mirrored).
BakeFile astc_cube_file(const std::string& name, const BakeInput& input, bool x_mirrored);

// The chain's roughness by level: lod = roughness x (levels - 1), each level's roughness.
Json chain_roughness_json(const PrefilteredChain& chain);

// The chain of the targets that ship the ASTC cube: the request's levels, size and samples, the cube
// projection, linear roughness.
std::optional<PrefilterParams> astc_cube_chain_params(const PrefilterRequest& request);

// What a desktop target's manifest adds to the common part; `roles` says what each file is for, in the
// order of the files.
struct DesktopManifest {
  EngineFrame frame;
  std::string face_order;
  Json roughness_to_lod;
  Json import;
  std::vector<std::string> roles;
};
// Appends manifest.json (manifest_common, then the frame, face order, roughness, the files with their
// sizes and roles, and the import settings) to `files`.
void add_manifest(std::vector<BakeFile>& files, const BakeInput& input, BakeTarget target,
                  const DesktopManifest& manifest);

}  // namespace lp::api
