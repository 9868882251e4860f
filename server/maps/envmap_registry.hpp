#pragma once
// The loaded environment maps, by id. Thread-safe; handlers hold a shared_ptr while they work, so a
// DELETE never pulls a map out from under a running request.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/projection/projection.hpp"

namespace lp::server {

struct EnvMapEntry {
  std::string id;
  std::string name;
  std::string format;  // "exr", "pfm", "hdr" or "procedural"
  std::string source;  // "upload", "path:<relative>", "procedural"
  std::shared_ptr<const EnvMap> map;
  std::chrono::system_clock::time_point created;
  Projection source_projection = Projection::LatLong;  // the file's layout, converted to lat-long on load
};

// Ids are the map names (server/storage/resource_name.hpp).
class EnvMapRegistry {
 public:
  explicit EnvMapRegistry(int64_t max_entries) : max_entries_(max_entries) {}

  // Throws ApiError 409 if the name is taken, 507 when full.
  std::shared_ptr<const EnvMapEntry> add(const std::string& name, std::string format, std::string source,
                                         std::shared_ptr<const EnvMap> map,
                                         Projection source_projection = Projection::LatLong);
  std::shared_ptr<const EnvMapEntry> find(const std::string& id) const;  // nullptr if absent
  std::shared_ptr<const EnvMapEntry> get(const std::string& id) const;   // throws ApiError 404
  bool remove(const std::string& id);
  std::vector<std::shared_ptr<const EnvMapEntry>> list() const;

 private:
  int64_t max_entries_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const EnvMapEntry>> entries_;
};

}  // namespace lp::server
