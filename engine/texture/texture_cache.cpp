#include "engine/texture/texture_cache.hpp"

namespace lp {

std::shared_ptr<const Texture> TextureCache::get(const std::string& key, ColorSpace space,
                                                 const std::function<Texture()>& decode) {
  const Key k{key, space};
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = textures_.find(k); it != textures_.end())
      if (auto alive = it->second.lock()) return alive;
  }
  // Decoded outside the lock: other textures stay available meanwhile. When two callers decode the same
  // texture at once, the first one stored wins and the other copy is dropped.
  auto texture = std::make_shared<const Texture>(decode());
  const std::lock_guard lock(mutex_);
  std::erase_if(textures_, [](const auto& entry) { return entry.second.expired(); });
  auto& slot = textures_[k];
  if (auto alive = slot.lock()) return alive;
  slot = texture;
  return texture;
}

size_t TextureCache::size() const {
  const std::lock_guard lock(mutex_);
  size_t n = 0;
  for (const auto& entry : textures_) n += entry.second.expired() ? 0 : 1;
  return n;
}

}  // namespace lp
