#pragma once
// The maps a worker renders with, by content hash (maps/envmap_content_hash.hpp): one of this server's own
// maps when it holds the same pixels, else fetched from the coordinator (GET /api/v1/content/{hash}, float
// OpenEXR, no larger than a map within --max-pixels can be), checked against the hash and kept for the
// next items (the last few, by last use). The download and the decoded pixels are reserved in the memory
// budget; a fetched map's pixels stay there, held, while it is kept or a renderer uses it.
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "server/app.hpp"
#include "server/scale_out/recent_list.hpp"

namespace lp::server {

class MapFetcher {
 public:
  explicit MapFetcher(App& app) : app_(app) {}

  // Throws std::runtime_error when the coordinator does not have it or sends other pixels.
  std::shared_ptr<const EnvMap> get(const std::string& hash, const std::string& source_url);

 private:
  std::shared_ptr<const EnvMap> own(const std::string& hash) const;
  std::shared_ptr<const EnvMap> fetch(const std::string& hash, const std::string& source_url) const;

  static constexpr size_t kKept = 4;
  App& app_;
  std::mutex mutex_;
  RecentList<std::string, std::shared_ptr<const EnvMap>> kept_{kKept};
};

}  // namespace lp::server
