// OIDN's tensor archive reader, and the network's checks of what it read, on any bytes.
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/denoise/denoiser.hpp"
#include "engine/denoise/tza.hpp"
#include "engine/denoise/unet.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const lp::denoise::TensorMap tensors = lp::denoise::parse_tza(std::span<const uint8_t>(data, size));
    const lp::denoise::UNet net(tensors, 9);
  } catch (const lp::denoise::DenoiseError&) {
  }
  return 0;
}
