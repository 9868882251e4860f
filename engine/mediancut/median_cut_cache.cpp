#include "engine/mediancut/median_cut_cache.hpp"

namespace lp {

std::shared_ptr<const MedianCutResult> MedianCutCache::find(const std::string& key) const {
  std::lock_guard lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->first != key) continue;
    entries_.splice(entries_.begin(), entries_, it);
    return entries_.front().second;
  }
  return nullptr;
}

void MedianCutCache::store(const std::string& key, std::shared_ptr<const MedianCutResult> result) const {
  std::lock_guard lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end(); ++it)
    if (it->first == key) {
      entries_.erase(it);
      break;
    }
  entries_.emplace_front(key, std::move(result));
  while (entries_.size() > capacity_) entries_.pop_back();
}

size_t MedianCutCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace lp
