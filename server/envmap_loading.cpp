#include "server/envmap_loading.hpp"

#include <chrono>

#include <spdlog/spdlog.h>

#include "api/api_error.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/envmap/procedural_sky.hpp"

namespace lp::server {
namespace {

// Checked before decoding so a bad name costs nothing; add() checks again under its lock.
void check_new_name(const App& app, const std::string& name) {
  if (!valid_envmap_name(name))
    throw api::invalid_field("name", "must be 1-64 characters of A-Z a-z 0-9 . _ - and not start with '.'");
  if (app.envmaps.find(name)) throw api::ApiError(409, "conflict", "an environment map named '" + name + "' exists");
}

std::shared_ptr<const EnvMapEntry> register_image(App& app, const std::string& name, DecodedImage decoded,
                                                  const std::string& format, const std::string& source,
                                                  InvalidPixelPolicy policy) {
  const auto start = std::chrono::steady_clock::now();
  auto map = std::make_shared<const EnvMap>(std::move(decoded.image), policy);
  map->sampler(LuminanceMode::Average);  // precompute the default distribution once, now
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto entry = app.envmaps.add(name, format, source, std::move(map));
  if (const auto& fixed = entry->map->invalid_pixels(); fixed.clamped_negative_values || fixed.non_finite_pixels)
    spdlog::warn("map '{}': clamped {} negative values (lowest {}) to zero and set {} non-finite pixels to black", name,
                 fixed.clamped_negative_values, fixed.most_negative_value, fixed.non_finite_pixels);
  spdlog::info("loaded map '{}' ({}x{} {}, from {}) in {:.1f} ms", name, entry->map->width(), entry->map->height(),
               entry->format, source, ms);
  return entry;
}

}  // namespace

ImageLimits image_limits(const Options& options) {
  ImageLimits limits;
  limits.max_pixels = options.max_pixels;
  return limits;
}

std::shared_ptr<const EnvMapEntry> register_envmap_bytes(App& app, const std::string& name, std::span<const uint8_t> bytes,
                                                         const std::string& source, InvalidPixelPolicy policy) {
  check_new_name(app, name);
  DecodedImage decoded = read_image(bytes, image_limits(app.options));
  return register_image(app, name, std::move(decoded), format_name(decoded.format), source, policy);
}

std::shared_ptr<const EnvMapEntry> register_envmap_file(App& app, const std::string& name,
                                                        const std::filesystem::path& path, const std::string& source,
                                                        InvalidPixelPolicy policy) {
  check_new_name(app, name);
  DecodedImage decoded = read_image_file(path, image_limits(app.options));
  return register_image(app, name, std::move(decoded), format_name(decoded.format), source, policy);
}

void register_default_envmap(App& app) {
  register_image(app, "default", {make_procedural_sky(), ImageFormat::Exr}, "procedural", "procedural",
                 InvalidPixelPolicy::Reject);
}

}  // namespace lp::server
