#pragma once
// Decoding and registering maps: the one path every map takes (--load, upload, data-dir path).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "engine/envmap/invalid_pixels.hpp"
#include "engine/projection/projection.hpp"
#include "server/app.hpp"

namespace lp::server {

// Decodes, converts a file in another projection to lat-long (api/projection_params.hpp: a shape that
// does not fit the projection is a 400 naming `projection`), applies the invalid-pixel policy,
// precomputes the default sampling distribution and registers the map.
std::shared_ptr<const EnvMapEntry> register_envmap_bytes(
    App& app, const std::string& name, std::span<const uint8_t> bytes, const std::string& source,
    InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy, Projection projection = Projection::LatLong);
std::shared_ptr<const EnvMapEntry> register_envmap_file(
    App& app, const std::string& name, const std::filesystem::path& path, const std::string& source,
    InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy, Projection projection = Projection::LatLong);
// The procedural sky, as "default".
void register_default_envmap(App& app);

ImageLimits image_limits(const Options& options);

// The pixels of an image being decoded, reserved before the reader allocates them: from the memory
// budget (they stay with the map) and from the share of it that decodes in flight may take together.
struct DecodeMemory {
  MemoryReservation pixels, decoding;
};
// The limits of --max-pixels, reserving the pixels in `memory` before a reader allocates them.
ImageLimits budgeted_limits(App& app, DecodeMemory& memory);

}  // namespace lp::server
