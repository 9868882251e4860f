#include "server/renders/render_coordinator.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <span>
#include <stdexcept>

#include "engine/render/partial_film_codec.hpp"
#include "server/scale_out/redis_keys.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
namespace keys = render_keys;

constexpr auto kNoticeWait = 500ms;
constexpr auto kRestoreEvery = 2s;
constexpr int kCancelKeyLifetimeS = 3600;  // longer than any item a worker may still be rendering

}  // namespace

RenderCoordinator::RenderCoordinator(const ScaleOut& scale_out, std::string render_id)
    : scale_out_(scale_out), id_(std::move(render_id)), redis_(scale_out.redis) {}

void RenderCoordinator::publish(const std::vector<render::SampleRange>& items) {
  redis_.del(
      {keys::items(id_), keys::partials(id_), keys::done(id_), keys::cancel(id_)});  // an earlier run's
  redis_.set(keys::job(id_), description_);
  redis_.xgroup_create(keys::items(id_), keys::kGroup);
  for (const auto& r : items)
    redis_.xadd(keys::items(id_), {{"first", std::to_string(r.first)}, {"end", std::to_string(r.end)}});
  redis_.sadd(keys::kActive, id_);
  scale_out_.counters->published.fetch_add(items.size(), std::memory_order_relaxed);
}

void RenderCoordinator::withdraw() {
  redis_.srem(keys::kActive, id_);
  redis_.del({keys::job(id_), keys::items(id_), keys::partials(id_), keys::done(id_)});
}

// Merges the partial of `range` once; false when Redis does not hold it.
bool RenderCoordinator::merge(const std::string& range, Merged& merged, const OnMerged& on_merged) {
  if (merged.ranges.contains(range)) return true;  // a duplicate delivery
  const auto bytes = redis_.hget(keys::partials(id_), range);
  if (!bytes) return false;
  const auto partial = render::decode_partial(
      std::span(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size()), merged.film.pixel_count());
  if (keys::range_field(partial.range) != range)
    throw std::runtime_error("a partial film under another range");
  merged.film.merge(partial.film);
  merged.ranges.insert(range);
  scale_out_.counters->merged.fetch_add(1, std::memory_order_relaxed);
  scale_out_.counters->outstanding.fetch_sub(1, std::memory_order_relaxed);
  redis_.hdel(keys::partials(id_), range);
  on_merged(merged.film, partial.range, partial.rays);
  return true;
}

void RenderCoordinator::read_notices(Merged& merged, std::chrono::milliseconds wait,
                                     const OnMerged& on_merged) {
  for (const StreamEntry& notice : redis_.xread(keys::done(id_), merged.last_notice, wait)) {
    merged.last_notice = notice.id;
    const std::string range = notice.field("range").value_or("");
    if (const auto error = notice.field("error")) {
      withdraw();
      throw std::runtime_error(fmt::format("a worker could not render samples {}: {}", range, *error));
    }
    merge(range, merged, on_merged);  // a partial Redis lost is issued again by restore()
  }
}

// Puts back what Redis lost. A range is in flight when its item waits in the stream (after the group's
// last delivered id) or a worker holds it (pending). The last delivered id is read before the pending
// ids and the notices after both: an item delivered in between is pending or, acknowledged, has its
// notice out already (a worker notifies before it acknowledges), so a range in flight is never taken for
// lost; at worst a duplicate is rendered, and merged once.
void RenderCoordinator::restore(const std::vector<render::SampleRange>& items, Merged& merged,
                                const OnMerged& on_merged) {
  const std::string stream = keys::items(id_);
  redis_.set_if_absent(keys::job(id_), description_);
  redis_.sadd(keys::kActive, id_);
  auto last_delivered = redis_.xgroup_last_delivered(stream, keys::kGroup);
  if (!last_delivered) {  // the group is gone: one from now on, every range not merged issued again
    redis_.xgroup_create(stream, keys::kGroup, "$");
    last_delivered = redis_.xgroup_last_delivered(stream, keys::kGroup).value_or("0-0");
  }
  const auto entries = redis_.xrange(stream);
  const auto pending = redis_.xpending(stream, keys::kGroup, int64_t(entries.size()) + 1);
  read_notices(merged, 0ms, on_merged);
  const std::set<std::string> held(pending.begin(), pending.end());
  std::set<std::string> in_flight;
  for (const auto& e : entries)
    if (held.contains(e.id) || stream_id_less(*last_delivered, e.id))
      in_flight.insert(e.field("first").value_or("") + "-" + e.field("end").value_or(""));
  for (const auto& r : items) {
    const std::string range = keys::range_field(r);
    if (merged.ranges.contains(range) || in_flight.contains(range) || merge(range, merged, on_merged))
      continue;
    redis_.xadd(stream, {{"first", std::to_string(r.first)}, {"end", std::to_string(r.end)}});
    scale_out_.counters->published.fetch_add(1, std::memory_order_relaxed);
    spdlog::warn("render {}: Redis lost samples {}; issued again", id_, range);
  }
}

bool RenderCoordinator::run(const RenderDescription& description,
                            const std::vector<render::SampleRange>& items, render::PartialFilm film,
                            const std::function<bool()>& stop, const OnMerged& on_merged) {
  description_ = description_json(description);
  publish(items);
  spdlog::info("render {}: {} work items of up to {} spp on {}", id_, items.size(), scale_out_.item_spp,
               scale_out_.redis.url());
  Merged merged;
  merged.film = std::move(film);
  // Outstanding while this run lasts, however it ends (merged ones leave the count as they arrive).
  auto& outstanding = scale_out_.counters->outstanding;
  outstanding.fetch_add(int64_t(items.size()), std::memory_order_relaxed);
  const struct Settle {
    std::atomic<int64_t>& count;
    const Merged& merged;
    const size_t items;
    ~Settle() { count.fetch_sub(int64_t(items - merged.ranges.size()), std::memory_order_relaxed); }
  } settle{outstanding, merged, items.size()};
  auto next_restore = Clock::now() + kRestoreEvery;
  while (merged.ranges.size() < items.size()) {
    if (stop()) {
      redis_.set(keys::cancel(id_), "1", kCancelKeyLifetimeS);
      withdraw();
      return false;
    }
    read_notices(merged, kNoticeWait, on_merged);
    if (Clock::now() >= next_restore) {
      try {
        restore(items, merged, on_merged);
      } catch (const RedisError& e) {  // Redis losing the group again meanwhile: the next round restores
        spdlog::warn("render {}: cannot restore its items yet: {}", id_, e.what());
      }
      next_restore = Clock::now() + kRestoreEvery;
    }
  }
  withdraw();
  return true;
}

}  // namespace lp::server
