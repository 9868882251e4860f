// The OBJ loader the product uses (pre-scan, tinyobjloader, index and vertex checks) on any text as an
// OBJ without a material library.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lp::ModelLimits limits;
  limits.max_triangles = 100000;
  try {
    lp::load_obj_memory(std::string(reinterpret_cast<const char*>(data), size), "", "fuzz.obj", limits);
  } catch (const lp::Error&) {
  }
  return 0;
}
