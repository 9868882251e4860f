// Any bytes through the magic-byte detector and the matching decoder, then into an environment map
// (invalid-pixel policy, power, sampling distribution) when they decode.
#include "decoder_fuzz.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lp::fuzz::decode(data, size, [](std::span<const uint8_t> bytes, const lp::ImageLimits& limits) {
    const lp::EnvMap map(lp::read_image(bytes, limits).image);
    map.sampler(lp::LuminanceMode::Average)->sample(0.5f, 0.5f);
  });
}
