#include "server/renders/render_worker.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>

#include "engine/render/partial_film_codec.hpp"
#include "server/jobs/job_arena.hpp"
#include "server/renders/scene_meshes.hpp"
#include "server/scale_out/redis_keys.hpp"
#include "server/scale_out/render_description.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
namespace keys = render_keys;

constexpr auto kItemWait = 1000ms;
constexpr auto kIdleWait = 50ms;    // between reads of the active renders while there is none
constexpr auto kRetryWait = 300ms;  // after a failure
constexpr auto kCancelCheckEvery = 100ms;
constexpr int kPartialLifetimeS = 3600;  // the coordinator merges a partial within a second of its notice

// Asks Redis whether a render was cancelled, at most every kCancelCheckEvery whichever render thread
// asks; sets `cancel` when it was (or the worker is stopping).
class CancelWatch {
 public:
  CancelWatch(RedisClient& redis, std::string key, const std::stop_token& stop, std::atomic<bool>& cancel)
      : redis_(redis), key_(std::move(key)), stop_(stop), cancel_(cancel) {}

  void check() {
    const int64_t now = Clock::now().time_since_epoch().count();
    int64_t last = last_.load();
    if (now - last < std::chrono::nanoseconds(kCancelCheckEvery).count() ||
        !last_.compare_exchange_strong(last, now))
      return;
    try {
      if (stop_.stop_requested() || redis_.exists(key_)) cancel_.store(true);
    } catch (const RedisError& e) {
      spdlog::warn("worker: cannot check for a cancel: {}", e.what());
    }
  }

 private:
  RedisClient& redis_;
  const std::string key_;
  const std::stop_token& stop_;
  std::atomic<bool>& cancel_;
  std::atomic<int64_t> last_{0};
};

bool ended_render(const RedisError& e) {
  const std::string_view message = e.what();
  return message.find("UNBLOCKED") != message.npos || message.find("NOGROUP") != message.npos;
}

}  // namespace

std::string worker_name() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return fmt::format("{}-{}", host, getpid());
}

RenderWorker::RenderWorker(App& app, std::string consumer)
    : app_(app),
      consumer_(std::move(consumer)),
      redis_(*app.options.scale_out.redis),
      cancel_check_(*app.options.scale_out.redis, 5s),
      maps_(app),
      bundles_(app),
      heartbeat_(*app.options.scale_out.redis, consumer_),
      thread_([this](std::stop_token stop) { loop(stop); }) {}

RenderWorker::~RenderWorker() {
  thread_.request_stop();
}

void RenderWorker::loop(const std::stop_token& stop) {
  spdlog::info("worker {}: taking render items from {}", consumer_, app_.options.scale_out.redis->url());
  JobArena arena(app_.options.threads, app_.options.jobs.render_priority);
  while (!stop.stop_requested()) {
    try {
      if (const auto item = next_item()) arena.execute([&] { take(*item, stop); });
    } catch (const RedisError& e) {
      // A render that ended while this worker waited on its stream: read the active renders again.
      if (ended_render(e)) continue;
      spdlog::warn("worker {}: {}", consumer_, e.what());
      std::this_thread::sleep_for(kRetryWait);
    } catch (const std::exception& e) {
      spdlog::warn("worker {}: {}", consumer_, e.what());
      std::this_thread::sleep_for(kRetryWait);
    }
  }
}

// An item a dead worker held first, else a new one (waiting up to kItemWait).
std::optional<StreamEntry> RenderWorker::next_item() {
  std::vector<std::string> streams;
  for (const auto& id : redis_.smembers(keys::kActive)) streams.push_back(keys::items(id));
  if (streams.empty()) {
    std::this_thread::sleep_for(kIdleWait);
    return std::nullopt;
  }
  const std::chrono::milliseconds claim_after(int64_t(app_.options.scale_out.claim_timeout_s) * 1000);
  for (const auto& stream : streams) {
    for (const auto& orphan : orphaned_items(redis_, stream, keys::kGroup))
      for (auto& entry : redis_.xclaim(stream, keys::kGroup, consumer_, kHeartbeatLifetime, orphan)) {
        spdlog::info("worker {}: took over item {} of {} from a worker without a heartbeat", consumer_,
                     entry.id, stream);
        app_.scale_out_counters.taken_over.fetch_add(1, std::memory_order_relaxed);
        return std::move(entry);
      }
    for (auto& entry : redis_.xautoclaim(stream, keys::kGroup, consumer_, claim_after)) {
      spdlog::info("worker {}: took over item {} of {}", consumer_, entry.id, stream);
      app_.scale_out_counters.taken_over.fetch_add(1, std::memory_order_relaxed);
      return std::move(entry);
    }
  }
  auto entries = redis_.xreadgroup(keys::kGroup, consumer_, streams, kItemWait);
  if (entries.empty()) return std::nullopt;
  return std::move(entries.front());
}

void RenderWorker::take(const StreamEntry& item, const std::stop_token& stop) {
  const std::string id = keys::id_of_items(item.stream);
  const auto range =
      keys::parse_range(item.field("first").value_or("") + "-" + item.field("end").value_or(""));
  if (id.empty() || !range) {
    spdlog::warn("worker {}: a malformed item {} in {}", consumer_, item.id, item.stream);
    redis_.xack(item.stream, keys::kGroup, item.id);
    return;
  }
  const std::string field = keys::range_field(*range);
  try {
    if (!render(id, *range, stop) && stop.stop_requested()) return;  // another worker will take it
  } catch (const RedisError&) {
    throw;
  } catch (const std::exception& e) {
    spdlog::warn("worker {}: render {} samples {}: {}", consumer_, id, field, e.what());
    redis_.xadd(keys::done(id), {{"range", field}, {"error", e.what()}});
  }
  redis_.xack(item.stream, keys::kGroup, item.id);
}

// Renders the range, uploads it and notifies the coordinator; false if it stopped early (cancelled or
// stopping) or the render is gone.
bool RenderWorker::render(const std::string& id, render::SampleRange range, const std::stop_token& stop) {
  render::Renderer* renderer = renderer_for(id);
  if (!renderer) return false;
  const std::string field = keys::range_field(range);
  spdlog::info("worker {}: render {} samples {} started", consumer_, id, field);
  std::atomic<bool> cancel{false};
  CancelWatch watch(cancel_check_, keys::cancel(id), stop, cancel);
  const auto start = Clock::now();
  const auto partial = renderer->render_range(range, cancel, [&watch] { watch.check(); });
  if (!partial) {
    spdlog::info("worker {}: render {} samples {} cancelled", consumer_, id, field);
    return false;
  }
  const auto bytes = render::encode_partial(*partial);
  redis_.hset(keys::partials(id), field,
              std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  redis_.expire(keys::partials(id), kPartialLifetimeS);  // a duplicate after the render ended goes too
  redis_.xadd(keys::done(id), {{"range", field}, {"rays", std::to_string(partial->rays)}});
  app_.scale_out_counters.rendered.fetch_add(1, std::memory_order_relaxed);
  spdlog::info("worker {}: render {} samples {} done in {:.3f} s", consumer_, id, field,
               std::chrono::duration<double>(Clock::now() - start).count());
  return true;
}

render::Renderer* RenderWorker::renderer_for(const std::string& id) {
  if (loaded_ && loaded_->id == id) return loaded_->renderer.get();
  loaded_.reset();
  const auto text = redis_.get(keys::job(id));
  if (!text) return nullptr;
  const RenderDescription description = parse_description(*text);
  Loaded next{id, api::parse_render_request(description.request, app_.options.limits), nullptr};
  resolve_meshes(next.request.scene, app_, [&](size_t object, const std::string&, const std::string& field) {
    const MeshReference* mesh = description.mesh(object);
    if (!mesh) throw std::runtime_error("the render's description names no mesh bundle for " + field);
    return bundles_.model_file(*mesh, description.source_url, field);
  });
  const auto map = maps_.get(description.envmap_hash, description.source_url);
  next.renderer = std::make_unique<render::Renderer>(next.request.scene, next.request.lighting,
                                                     next.request.settings, map);
  loaded_ = std::move(next);
  return loaded_->renderer.get();
}

}  // namespace lp::server
