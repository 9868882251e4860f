#pragma once
// Decoding and registering maps: the one path every map takes (--load, upload, data-dir path).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "engine/envmap/invalid_pixels.hpp"
#include "server/app.hpp"

namespace lp::server {

// Decodes, applies the invalid-pixel policy, precomputes the default sampling distribution and
// registers the map.
std::shared_ptr<const EnvMapEntry> register_envmap_bytes(
    App& app, const std::string& name, std::span<const uint8_t> bytes, const std::string& source,
    InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy);
std::shared_ptr<const EnvMapEntry> register_envmap_file(
    App& app, const std::string& name, const std::filesystem::path& path, const std::string& source,
    InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy);
// The procedural sky, as "default".
void register_default_envmap(App& app);

ImageLimits image_limits(const Options& options);

}  // namespace lp::server
