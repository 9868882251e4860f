#include "engine/core/memory_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace lp {

struct MemoryBudget::State {
  struct Entry {
    int64_t bytes = 0;
    MemoryUse use = MemoryUse::Transient;
    std::function<void()> evict;  // cache entries not yet chosen for eviction
    uint64_t last_use = 0;
  };

  explicit State(int64_t cap) : capacity(cap) {}

  int64_t& used_by(MemoryUse use) { return used[size_t(use)]; }
  void add(Entry& e, int64_t bytes) {
    e.bytes += bytes;
    used_by(e.use) += bytes;
    total += bytes;
  }

  // Takes cache entries out, least recently used first, until they hold `shortfall` bytes; returns
  // their evict functions (to call without the lock).
  std::vector<std::function<void()>> pick_victims(int64_t shortfall) {
    std::vector<Entry*> candidates;
    for (auto& [id, e] : entries)
      if (e.evict) candidates.push_back(&e);
    std::sort(candidates.begin(), candidates.end(),
              [](auto* a, auto* b) { return a->last_use < b->last_use; });
    std::vector<std::function<void()>> victims;
    for (Entry* e : candidates) {
      if (shortfall <= 0) break;
      victims.push_back(std::exchange(e->evict, nullptr));
      shortfall -= e->bytes;
    }
    return victims;
  }

  [[noreturn]] void refuse(int64_t bytes, std::string_view what) const {
    const int64_t held = used[size_t(MemoryUse::Held)];
    throw MemoryBudgetError(
        fmt::format(
            "not enough memory for {}: it needs {}, {} of the {} budget are free ({} held, {} in use by work "
            "in flight)",
            what, format_mib(bytes), format_mib(capacity - total), format_mib(capacity), format_mib(held),
            format_mib(total - held)),
        bytes <= capacity - held);
  }

  // Makes room for `bytes` more, evicting cache entries (the lock is released meanwhile); throws if
  // there is no more to evict and they still do not fit.
  void make_room(std::unique_lock<std::mutex>& lock, int64_t bytes, std::string_view what) {
    if (bytes > capacity)
      throw MemoryBudgetError(
          fmt::format("not enough memory for {}: it needs {}, more than the whole {} budget", what,
                      format_mib(bytes), format_mib(capacity)),
          false);
    while (total + bytes > capacity) {
      const auto victims = pick_victims(total + bytes - capacity);
      if (victims.empty()) refuse(bytes, what);
      lock.unlock();
      for (const auto& evict : victims) evict();
      lock.lock();
    }
  }

  std::mutex mutex;
  const int64_t capacity;
  int64_t used[3] = {};
  int64_t total = 0;
  uint64_t next_id = 1, clock = 0;
  std::map<uint64_t, Entry> entries;
};

MemoryBudget::MemoryBudget(int64_t capacity_bytes) : state_(std::make_shared<State>(capacity_bytes)) {}

MemoryReservation MemoryBudget::reserve(int64_t bytes, MemoryUse use, std::string_view what) const {
  return grant(bytes, use, what, nullptr);
}

MemoryReservation MemoryBudget::reserve_cache(int64_t bytes, std::string_view what,
                                              std::function<void()> evict) const {
  return grant(bytes, MemoryUse::Cache, what, std::move(evict));
}

MemoryReservation MemoryBudget::grant(int64_t bytes, MemoryUse use, std::string_view what,
                                      std::function<void()> evict) const {
  bytes = std::max<int64_t>(bytes, 0);
  std::unique_lock lock(state_->mutex);
  state_->make_room(lock, bytes, what);
  const uint64_t id = state_->next_id++;
  auto& e = state_->entries[id];
  e.use = use;
  e.evict = std::move(evict);
  e.last_use = ++state_->clock;
  state_->add(e, bytes);
  return MemoryReservation(state_, id, bytes);
}

int64_t MemoryBudget::capacity() const {
  return state_->capacity;
}

int64_t MemoryBudget::used() const {
  std::lock_guard lock(state_->mutex);
  return state_->total;
}

int64_t MemoryBudget::used(MemoryUse use) const {
  std::lock_guard lock(state_->mutex);
  return state_->used_by(use);
}

MemoryReservation::MemoryReservation(MemoryReservation&& other) noexcept
    : state_(std::move(other.state_)), id_(other.id_), bytes_(std::exchange(other.bytes_, 0)) {}

MemoryReservation& MemoryReservation::operator=(MemoryReservation&& other) noexcept {
  if (this != &other) {
    release();
    state_ = std::move(other.state_);
    id_ = other.id_;
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void MemoryReservation::resize(int64_t bytes) {
  if (!state_) return;
  bytes = std::max<int64_t>(bytes, 0);
  std::unique_lock lock(state_->mutex);
  if (bytes > bytes_) state_->make_room(lock, bytes - bytes_, "a growing reservation");
  state_->add(state_->entries.at(id_), bytes - bytes_);
  bytes_ = bytes;
}

void MemoryReservation::set_use(MemoryUse use) {
  if (!state_) return;
  std::lock_guard lock(state_->mutex);
  auto& e = state_->entries.at(id_);
  state_->used_by(e.use) -= e.bytes;
  e.use = use;
  state_->used_by(use) += e.bytes;
  if (use != MemoryUse::Cache) e.evict = nullptr;
}

void MemoryReservation::touch() const {
  if (!state_) return;
  std::lock_guard lock(state_->mutex);
  state_->entries.at(id_).last_use = ++state_->clock;
}

void MemoryReservation::release() {
  if (!state_) return;
  {
    std::lock_guard lock(state_->mutex);
    auto it = state_->entries.find(id_);
    state_->add(it->second, -it->second.bytes);
    state_->entries.erase(it);
  }
  state_.reset();
  bytes_ = 0;
}

std::string format_mib(int64_t bytes) {
  return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20));
}

}  // namespace lp
