#include "server/maps/envmap_loading.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <system_error>

#include "api/api_error.hpp"
#include "api/builtin_maps.hpp"
#include "api/projection_params.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/projection/reproject.hpp"
#include "server/storage/resource_name.hpp"

namespace lp::server {
namespace {

// Checked before decoding so a bad name costs nothing; add() checks again under its lock.
void check_new_name(const App& app, const std::string& name) {
  if (!valid_resource_name(name)) throw api::invalid_field("name", std::string(kResourceNameRule));
  if (app.envmaps.find(name))
    throw api::ApiError(api::ErrorCode::Conflict, "an environment map named '" + name + "' exists");
}

void reserve_or_resize(MemoryReservation& r, const MemoryBudget& budget, int64_t bytes,
                       const std::string& what) {
  if (r)
    r.resize(bytes);
  else
    r = budget.reserve(bytes, MemoryUse::Transient, what);
}

// An image in another projection becomes a lat-long map: its bad pixels are fixed (or refused, naming the
// file's pixel) first, so none spreads over its neighbours; `pixels` then holds the converted image's
// bytes, reserved before the conversion. What the policy changed.
InvalidPixelReport convert_to_latlong(App& app, Image& image, Projection projection,
                                      InvalidPixelPolicy policy, MemoryReservation& pixels) {
  if (projection == Projection::LatLong) return {};
  const int width =
      api::input_latlong_width(projection, image.width(), image.height(), app.options.limits.max_pixels);
  MemoryReservation converted =
      app.memory.reserve(EnvMap::image_bytes(width, width / 2), MemoryUse::Transient,
                         fmt::format("converting a {} map to lat-long", enum_name(projection)));
  const InvalidPixelReport fixed = sanitize_radiance(image, policy);
  image = reproject(image, projection, Projection::LatLong, width);
  pixels = std::move(converted);
  return fixed;
}

// `pixels` holds the image's bytes; they stay with the map.
std::shared_ptr<const EnvMapEntry> register_image(App& app, const std::string& name, DecodedImage decoded,
                                                  const std::string& format, const std::string& source,
                                                  InvalidPixelPolicy policy, MemoryReservation pixels,
                                                  Projection projection = Projection::LatLong) {
  const auto start = std::chrono::steady_clock::now();
  const InvalidPixelReport fixed_in_file = convert_to_latlong(app, decoded.image, projection, policy, pixels);
  auto map = std::make_shared<EnvMap>(std::move(decoded.image), policy, fixed_in_file);
  pixels.set_use(MemoryUse::Held);
  map->account_memory(app.memory, std::move(pixels));
  map->sampler(LuminanceMode::Average);  // precompute the default distribution once, now
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto entry = app.envmaps.add(name, format, source, std::move(map), projection);
  if (const auto& fixed = entry->map->invalid_pixels();
      fixed.clamped_negative_values || fixed.non_finite_pixels)
    spdlog::warn(
        "map '{}': clamped {} negative values (lowest {}) to zero and set {} non-finite pixels to black",
        name, fixed.clamped_negative_values, fixed.most_negative_value, fixed.non_finite_pixels);
  spdlog::info(
      "loaded map '{}' ({}x{} {}{}, from {}) in {:.1f} ms", name, entry->map->width(), entry->map->height(),
      entry->format,
      projection == Projection::LatLong ? "" : std::string(" converted from ") + enum_name(projection),
      source, ms);
  return entry;
}

}  // namespace

ImageLimits budgeted_limits(App& app, DecodeMemory& memory) {
  ImageLimits limits = image_limits(app.options);
  limits.before_allocation = [&app, &memory](int64_t width, int64_t height) {
    const int64_t bytes = EnvMap::image_bytes(width, height);
    const std::string what = fmt::format("decoding a {}x{} image", width, height);
    reserve_or_resize(memory.decoding, app.decoding, bytes, what + " (with the decodes in flight)");
    reserve_or_resize(memory.pixels, app.memory, bytes, what);
  };
  return limits;
}

ImageLimits image_limits(const Options& options) {
  ImageLimits limits;
  limits.max_pixels = options.limits.max_pixels;
  return limits;
}

std::shared_ptr<const EnvMapEntry> register_envmap_bytes(App& app, const std::string& name,
                                                         std::span<const uint8_t> bytes,
                                                         const std::string& source, InvalidPixelPolicy policy,
                                                         Projection projection) {
  check_new_name(app, name);
  DecodeMemory memory;
  DecodedImage decoded = read_image(bytes, budgeted_limits(app, memory));
  return register_image(app, name, std::move(decoded), enum_name(decoded.format), source, policy,
                        std::move(memory.pixels), projection);
}

std::shared_ptr<const EnvMapEntry> register_envmap_file(App& app, const std::string& name,
                                                        const std::filesystem::path& path,
                                                        const std::string& source, InvalidPixelPolicy policy,
                                                        Projection projection) {
  check_new_name(app, name);
  std::error_code unknown_size;
  const auto file_bytes = std::filesystem::file_size(path, unknown_size);
  const MemoryReservation file = app.memory.reserve(
      unknown_size ? 0 : int64_t(file_bytes), MemoryUse::Transient, "reading the file of map '" + name + "'");
  DecodeMemory memory;
  DecodedImage decoded = read_image_file(path, budgeted_limits(app, memory));
  return register_image(app, name, std::move(decoded), enum_name(decoded.format), source, policy,
                        std::move(memory.pixels), projection);
}

void register_default_envmap(App& app) {
  Image sky = *api::builtin_map(api::kDefaultEnvmapName);
  auto pixels =
      app.memory.reserve(EnvMap::image_bytes(sky.width(), sky.height()), MemoryUse::Held, "the default map");
  register_image(app, std::string(api::kDefaultEnvmapName), {std::move(sky), ImageFormat::Exr}, "procedural",
                 "procedural", InvalidPixelPolicy::Reject, std::move(pixels));
}

}  // namespace lp::server
