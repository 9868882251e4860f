#include "server/scale_out/map_fetcher.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <span>
#include <stdexcept>

#include "server/maps/envmap_content_hash.hpp"
#include "server/maps/envmap_loading.hpp"
#include "server/scale_out/content_download.hpp"

namespace lp::server {
namespace {

// The largest OpenEXR file of a map within the limits: float RGBA without compression (16 B/px), a
// scanline's offset and chunk header (16 B) per row, and the header.
int64_t largest_map_file_bytes(const ImageLimits& limits) {
  return 16 * limits.max_pixels + 16 * int64_t(limits.max_dimension) + (1 << 20);
}

}  // namespace

std::shared_ptr<const EnvMap> MapFetcher::get(const std::string& hash, const std::string& source_url) {
  {
    std::lock_guard lock(mutex_);
    if (const auto* kept = kept_.use(hash)) return *kept;
  }
  auto map = own(hash);
  if (!map) map = fetch(hash, source_url);
  std::lock_guard lock(mutex_);
  kept_.add(hash, map);
  return map;
}

std::shared_ptr<const EnvMap> MapFetcher::own(const std::string& hash) const {
  for (const auto& entry : app_.envmaps.list())
    if (envmap_content_hash(*entry->map) == hash) return entry->map;
  return nullptr;
}

std::shared_ptr<const EnvMap> MapFetcher::fetch(const std::string& hash,
                                                const std::string& source_url) const {
  DecodeMemory memory;
  const ImageLimits limits = budgeted_limits(app_, memory);
  Image image;
  int64_t file_bytes = 0;
  {
    const Download download =
        download_content(app_, source_url, hash, largest_map_file_bytes(limits), "the map " + hash);
    file_bytes = int64_t(download.bytes.size());
    image = read_exr(
        std::span(reinterpret_cast<const uint8_t*>(download.bytes.data()), download.bytes.size()), limits);
  }
  auto map = std::make_shared<EnvMap>(std::move(image));
  memory.pixels.set_use(MemoryUse::Held);
  map->account_memory(app_.memory, std::move(memory.pixels));
  if (envmap_content_hash(*map) != hash)
    throw std::runtime_error(fmt::format("the map fetched from {} is not {}", source_url, hash));
  spdlog::info("fetched map {} from {} ({} bytes)", hash, source_url, file_bytes);
  return map;
}

}  // namespace lp::server
