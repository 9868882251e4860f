// The OBJ mesh loader (pre-scan, tinyobjloader, index and vertex checks) on any text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/mesh_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lp::render::MeshLimits limits;
  limits.max_triangles = 100000;
  try {
    lp::render::obj_mesh_from_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.obj", {},
                                   limits);
  } catch (const lp::Error&) {
  }
  return 0;
}
