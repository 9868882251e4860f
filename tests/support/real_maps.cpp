#include "support/real_maps.hpp"

#include <map>
#include <mutex>

#include "engine/image/image_io.hpp"
#include "support/test_data.hpp"

namespace lp::test {

std::shared_ptr<const EnvMap> real_map(const std::string& file) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const EnvMap>> cache;
  std::lock_guard lock(mutex);
  auto& slot = cache[file];
  if (!slot) {
    slot = std::make_shared<const EnvMap>(read_image_file(envmap_path(file)).image);
  }
  return slot;
}

}  // namespace lp::test
