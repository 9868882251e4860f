// The glTF loader (schema check, tinygltf, accessors, node graph, materials, embedded textures) and the
// description of what it loads (bounds, extensions and warnings) on any bytes, as .gltf JSON or, when
// they start with "glTF", as .glb (its header and chunk table checked first), up to the size of a real
// asset's .glb.
// fuzz-dictionary: gltf.dict
// fuzz-max-len: 2097152
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/core/error.hpp"
#include "engine/model/model_info.hpp"
#include "engine/model/model_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lp::ModelLimits limits;
  limits.max_triangles = 100000;
  limits.max_texture_pixels = int64_t{1} << 20;
  limits.max_total_texture_pixels = int64_t{1} << 21;
  try {
    lp::describe_model(lp::load_gltf_memory(std::span<const uint8_t>(data, size), "fuzz.gltf", limits));
  } catch (const lp::Error&) {
  }
  return 0;
}
