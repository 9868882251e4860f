#pragma once
// A byte budget that work reserves from before it allocates, so that concurrent work cannot together
// go over it. A reservation is an RAII handle: its bytes return to the budget when it is destroyed or
// released, on every path. Cache entries (data derived from other data, which can be rebuilt) are
// evicted, least recently used first, to make room before a reservation is refused.
#include <climits>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "engine/core/error.hpp"

namespace lp {

enum class MemoryUse {
  Held,       // kept until a client deletes it (a loaded map, a finished result)
  Transient,  // released when the work in flight ends (decoding, encoding, a running render)
  Cache,      // derivable: evicted to make room (see MemoryBudget::reserve_cache)
};

// A reservation the budget cannot grant. transient(): the memory is taken by work in flight (or by
// evicted cache entries still in use), so the same request can succeed later; otherwise it cannot fit
// while the held data stays, or ever.
class MemoryBudgetError : public Error {
 public:
  MemoryBudgetError(const std::string& message, bool transient)
      : Error(ErrorKind::TooLarge, message), transient_(transient) {}
  bool transient() const { return transient_; }

 private:
  bool transient_;
};

class MemoryReservation;

class MemoryBudget {
 public:
  static constexpr int64_t kUnlimited = INT64_MAX;
  explicit MemoryBudget(int64_t capacity_bytes = kUnlimited);

  // Reserves `bytes` for `what` (named in the refusal), evicting cache entries if needed; throws
  // MemoryBudgetError if they still do not fit.
  MemoryReservation reserve(int64_t bytes, MemoryUse use, std::string_view what) const;
  // Reserves a cache entry's bytes. `evict` drops the entry from its cache; the budget calls it at most
  // once, without holding its lock, from whichever thread needs room. The bytes return when the
  // reservation is destroyed (with the entry's last user), not when `evict` returns.
  MemoryReservation reserve_cache(int64_t bytes, std::string_view what, std::function<void()> evict) const;

  int64_t capacity() const;
  int64_t used() const;
  int64_t used(MemoryUse use) const;

  struct State;

 private:
  MemoryReservation grant(int64_t bytes, MemoryUse use, std::string_view what,
                          std::function<void()> evict) const;

  std::shared_ptr<State> state_;
};

class MemoryReservation {
 public:
  MemoryReservation() = default;
  ~MemoryReservation() { release(); }
  MemoryReservation(MemoryReservation&& other) noexcept;
  MemoryReservation& operator=(MemoryReservation&& other) noexcept;
  MemoryReservation(const MemoryReservation&) = delete;
  MemoryReservation& operator=(const MemoryReservation&) = delete;

  int64_t bytes() const { return bytes_; }
  explicit operator bool() const { return state_ != nullptr; }

  // Grows (reserved like a new reservation: may evict, may throw) or shrinks (freed at once).
  void resize(int64_t bytes);
  // The same bytes, now counted as `use` (a decoded image kept as a map becomes Held).
  void set_use(MemoryUse use);
  // Marks a cache entry as just used, so it is evicted after the entries used before it.
  void touch() const;
  void release();

 private:
  friend class MemoryBudget;
  MemoryReservation(std::shared_ptr<MemoryBudget::State> state, uint64_t id, int64_t bytes)
      : state_(std::move(state)), id_(id), bytes_(bytes) {}

  std::shared_ptr<MemoryBudget::State> state_;
  uint64_t id_ = 0;
  int64_t bytes_ = 0;
};

// "12.5 MiB": sizes in refusals and logs.
std::string format_mib(int64_t bytes);

}  // namespace lp
