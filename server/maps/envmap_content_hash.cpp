#include "server/maps/envmap_content_hash.hpp"

#include <fmt/format.h>

#include <span>

#include "server/storage/content_hash.hpp"

namespace lp::server {

std::string envmap_content_hash(const EnvMap& map) {
  const auto value = map.derived<std::string>("content hash", [&map] {
    const auto pixels = std::as_bytes(map.image().data());
    ContentHasher hasher;
    hasher.add_number(uint64_t(map.width())).add_number(uint64_t(map.height())).add_number(pixels.size());
    hasher.add(pixels);
    return std::make_shared<const std::string>(
        fmt::format("{}-{}x{}", hasher.hex(), map.width(), map.height()));
  });
  return *value;
}

}  // namespace lp::server
