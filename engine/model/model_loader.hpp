#pragma once
// Models from files: glTF 2.0 (.gltf with external or data-URI buffers and images, .glb) through
// tinygltf, Wavefront OBJ with its MTL materials through tinyobjloader.
//
// glTF: the default scene (else the first; else every node without a parent) with each node's
// transform applied down the hierarchy; every primitive of mode triangles, triangle strip or triangle
// fan (points and lines are skipped); POSITION, NORMAL (flat normals when absent), TEXCOORD_0, TANGENT
// (generated when absent); metallic-roughness materials with their textures, samplers' wrap modes,
// KHR_texture_transform and KHR_materials_ior, _specular, _transmission, _volume, _clearcoat and
// _sheen (MaterialLobes). Texture filters are not read: lookups are always trilinear. Textures must use
// TEXCOORD_0.
//
// OBJ/MTL: Kd -> base colour, map_Kd -> base-colour texture (multiplied by Kd, as MTL defines), Ns ->
// roughness (below), map_Bump / bump / norm -> tangent-space normal map (-bm -> normal scale), Ke and
// map_Ke -> emission, -clamp -> clamp-to-edge wrapping, -o and -s -> texture transform. Metallic is 0.
// The Phong exponent Ns becomes roughness by Walter et al.'s (2007) match of the Phong and Beckmann
// lobes, alpha = sqrt(2 / (Ns + 2)), taken as GGX alpha; glTF's perceptual roughness is its square
// root: roughness = (2 / (Ns + 2))^(1/4) (Ns 0 -> 1, Ns 10 -> 0.64, Ns 1000 -> 0.21). OBJ texture
// coordinates (v up) are flipped to glTF's (v down). Faces without a material get a grey diffuse one.
//
// Every malformed input is an lp::Error naming what is wrong: Corrupt (unparseable, indices or
// accessors out of range, wrong component types, non-finite values, a recursive node graph), NotFound
// (a missing buffer or image), Unsupported (required extensions, sparse accessors, other texture
// coordinate sets), InvalidArgument (a file reference outside the model's folder), TooLarge (over a
// limit: checked before the triangles, file bytes or texels are allocated).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "engine/model/model.hpp"
#include "engine/texture/texture_cache.hpp"

namespace lp {

// "glb", "gltf" or "obj" for the name of a model file load_model reads (its extension, in any case),
// else "".
std::string model_format(const std::filesystem::path& path);

// By extension: .gltf, .glb or .obj. Textures come from `cache` when it holds them (and are kept
// there while the model lives); without a cache the model's textures are shared only within it.
Model load_model(const std::filesystem::path& path, const ModelLimits& limits, TextureCache* cache = nullptr);

// From memory, referring to no other file (buffers and images must be embedded): a .glb when the bytes
// start with its magic "glTF", else .gltf JSON. `name` appears in messages.
Model load_gltf_memory(std::span<const uint8_t> bytes, const std::string& name, const ModelLimits& limits);
// An OBJ and the text of its material library (used when the OBJ has a `mtllib` line). Texture
// files cannot be read from memory: a material naming one is an error.
Model load_obj_memory(const std::string& obj, const std::string& mtl, const std::string& name,
                      const ModelLimits& limits);

}  // namespace lp
