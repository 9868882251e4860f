// The Babylon .env reader alone, on any bytes.
#include <span>

#include "engine/core/error.hpp"
#include "engine/image/babylon_env.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    lp::read_babylon_env(std::span<const uint8_t>(data, size));
  } catch (const lp::Error&) {
  }
  return 0;
}
