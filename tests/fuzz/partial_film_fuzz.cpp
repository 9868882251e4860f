// The partial-film decoder (what a render worker uploads to Redis), on any bytes.
#include "decoder_fuzz.hpp"
#include "engine/render/partial_film_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lp::fuzz::decode(data, size, [](std::span<const uint8_t> bytes, const lp::ImageLimits& limits) {
    lp::render::decode_partial(bytes, limits.max_pixels);
  });
}
