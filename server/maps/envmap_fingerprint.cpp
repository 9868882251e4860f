#include "server/maps/envmap_fingerprint.hpp"

#include <fmt/format.h>

#include <functional>
#include <string_view>

namespace lp::server {

std::string envmap_fingerprint(const EnvMap& map) {
  const auto value = map.derived<std::string>("fingerprint", [&map] {
    const auto pixels = map.image().data();
    const std::string_view bytes(reinterpret_cast<const char*>(pixels.data()), pixels.size_bytes());
    return std::make_shared<const std::string>(
        fmt::format("{:016x}-{}x{}", std::hash<std::string_view>{}(bytes), map.width(), map.height()));
  });
  return *value;
}

}  // namespace lp::server
