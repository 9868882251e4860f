#pragma once
// A small least-recently-used cache of median cut results for one map, so that repeated requests
// are free while a client sweeping over many counts cannot grow memory without bound.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

namespace lp {

struct MedianCutResult;

class MedianCutCache {
 public:
  explicit MedianCutCache(size_t capacity = 16) : capacity_(capacity) {}

  std::shared_ptr<const MedianCutResult> find(const std::string& key) const;
  void store(const std::string& key, std::shared_ptr<const MedianCutResult> result) const;
  size_t size() const;

 private:
  size_t capacity_;
  mutable std::mutex mutex_;
  mutable std::list<std::pair<std::string, std::shared_ptr<const MedianCutResult>>> entries_;  // most recent first
};

}  // namespace lp
