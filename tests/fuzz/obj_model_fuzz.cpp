// The OBJ/MTL loader the product uses (pre-scan, tinyobjloader, index and vertex checks) on any text: the
// bytes up to the first NUL are the OBJ, the rest its material library (none without a NUL).
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const size_t split = std::min(text.find('\0'), text.size());
  lp::ModelLimits limits;
  limits.max_triangles = 100000;
  try {
    lp::load_obj_memory(text.substr(0, split), split < text.size() ? text.substr(split + 1) : "", "fuzz.obj",
                        limits);
  } catch (const lp::Error&) {
  }
  return 0;
}
