#pragma once
// A few values by key, most recently used first: adding past the capacity drops the least recently used.
// Not thread-safe: its owner locks.
#include <algorithm>
#include <cstddef>
#include <list>
#include <utility>
#include <variant>
#include <vector>

namespace lp::server {

template <typename Key, typename Value = std::monostate>
class RecentList {
 public:
  using Entry = std::pair<Key, Value>;

  explicit RecentList(size_t capacity) : capacity_(capacity) {}

  // The value under `key`, made the most recently used; null if there is none.
  const Value* use(const Key& key) {
    const auto it =
        std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.first == key; });
    if (it == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it);
    return &entries_.front().second;
  }

  // `value` under `key` (replacing what was under it), the most recently used; returns what this
  // dropped past the capacity, least recently used last.
  std::vector<Entry> add(Key key, Value value) {
    entries_.remove_if([&](const Entry& e) { return e.first == key; });
    entries_.emplace_front(std::move(key), std::move(value));
    std::vector<Entry> dropped;
    while (entries_.size() > capacity_) {
      dropped.push_back(std::move(entries_.back()));
      entries_.pop_back();
    }
    return dropped;
  }

  // The most recently used value that `match` accepts, left where it is; null if none does.
  template <typename Match>
  const Value* find_if(Match match) const {
    for (const Entry& e : entries_)
      if (match(e.second)) return &e.second;
    return nullptr;
  }

 private:
  size_t capacity_;
  std::list<Entry> entries_;
};

}  // namespace lp::server
