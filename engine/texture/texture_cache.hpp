#pragma once
// Textures shared between the models that use them: one decoded texture (with its mip pyramid) per key
// and colour space while anything holds it. Keys name the source: a file's path and modification time,
// or a model file's identity and the index of an image embedded in it. Thread-safe.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "engine/texture/texture_decode.hpp"

namespace lp {

class TextureCache {
 public:
  // The texture of `key` in `space`: the shared one when it is alive, else `decode()`'s result, kept.
  std::shared_ptr<const Texture> get(const std::string& key, ColorSpace space,
                                     const std::function<Texture()>& decode);

  // Textures alive in the cache now.
  size_t size() const;

 private:
  using Key = std::pair<std::string, ColorSpace>;
  mutable std::mutex mutex_;
  std::map<Key, std::weak_ptr<const Texture>> textures_;
};

}  // namespace lp
