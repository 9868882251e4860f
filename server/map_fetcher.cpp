#include "server/map_fetcher.hpp"

#include <fmt/format.h>
#include <httplib.h>
#include <spdlog/spdlog.h>

#include <span>
#include <stdexcept>

#include "server/envmap_fingerprint.hpp"
#include "server/envmap_loading.hpp"

namespace lp::server {

std::shared_ptr<const EnvMap> MapFetcher::get(const std::string& hash, const std::string& source_url) {
  {
    std::lock_guard lock(mutex_);
    for (auto it = kept_.begin(); it != kept_.end(); ++it)
      if (it->first == hash) {
        kept_.splice(kept_.begin(), kept_, it);
        return it->second;
      }
  }
  auto map = own(hash);
  if (!map) map = fetch(hash, source_url);
  std::lock_guard lock(mutex_);
  kept_.emplace_front(hash, map);
  if (kept_.size() > kKept) kept_.pop_back();
  return map;
}

std::shared_ptr<const EnvMap> MapFetcher::own(const std::string& hash) const {
  for (const auto& entry : app_.envmaps.list())
    if (envmap_fingerprint(*entry->map) == hash) return entry->map;
  return nullptr;
}

std::shared_ptr<const EnvMap> MapFetcher::fetch(const std::string& hash,
                                                const std::string& source_url) const {
  httplib::Client client(source_url);
  client.set_connection_timeout(5);
  client.set_read_timeout(60);
  httplib::Headers headers;
  if (!app_.options.auth_token.empty()) headers.emplace("Authorization", "Bearer " + app_.options.auth_token);
  const auto res = client.Get("/api/v1/content/" + hash, headers);
  if (!res)
    throw std::runtime_error(
        fmt::format("cannot fetch map {} from {}: {}", hash, source_url, httplib::to_string(res.error())));
  if (res->status != 200)
    throw std::runtime_error(
        fmt::format("cannot fetch map {} from {}: status {}", hash, source_url, res->status));
  const ImageLimits limits = image_limits(app_.options);
  auto map = std::make_shared<const EnvMap>(
      read_exr(std::span(reinterpret_cast<const uint8_t*>(res->body.data()), res->body.size()), limits));
  if (envmap_fingerprint(*map) != hash)
    throw std::runtime_error(fmt::format("the map fetched from {} is not {}", source_url, hash));
  spdlog::info("fetched map {} from {} ({} bytes)", hash, source_url, res->body.size());
  return map;
}

}  // namespace lp::server
