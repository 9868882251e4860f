#pragma once
// Ultra HDR (Google's Ultra HDR Image Format 1.0, the gain map of Adobe's hdrgm XMP): one JPEG file that
// any viewer shows as SDR and an HDR-aware reader (three.js's UltraHDRLoader, Chrome, Android) turns back
// into radiance. The SDR base is the radiance clipped to [0, 1], sRGB encoded, so that everything within
// the SDR range is the base itself (gain near 0: also what three.js's loader, which applies the gain to
// sRGB-encoded values, reconstructs best); the gain map holds, per pixel and channel, log2 of the ratio
// HDR / SDR of the base as decoded, spread over [GainMapMin, GainMapMax] in 8 bits (Gamma 1). Written with
// libjpeg-turbo (engine/image/jpeg_turbo), both JPEGs at full resolution and 4:4:4.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ultrahdr_container.hpp"

namespace lp {

struct UltraHdrOptions {
  int base_quality = 95;       // of the SDR base, 1..100
  int gain_map_quality = 100;  // of the gain map, 1..100
};

// Throws lp::Error(InvalidArgument) for an empty image. Radiance above 2^20 is clipped there.
std::vector<uint8_t> encode_ultrahdr(const Image& radiance, const UltraHdrOptions& options = {});

struct DecodedUltraHdr {
  Image radiance;  // the HDR rendition at full boost (display headroom >= HDRCapacityMax)
  ultrahdr::GainMapParams params;
};

// The HDR rendition as the Ultra HDR specification reconstructs it: (SDR + OffsetSDR) x 2^(log2 boost)
// - OffsetHDR, SDR and HDR linear, the gain map sampled at the nearest pixel when its size differs.
// Throws lp::Error: Corrupt (any part missing or out of bounds), TooLarge (over `limits`).
DecodedUltraHdr decode_ultrahdr(std::span<const uint8_t> file, const ImageLimits& limits = {});

}  // namespace lp
