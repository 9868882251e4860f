#pragma once
// The worker's side of renders split over machines (--redis, --role worker or both): a thread that takes
// work items from the items streams of the active renders (XREADGROUP in the consumer group; first the
// items of workers whose heartbeat stopped (worker_heartbeat.hpp: a few seconds after they died), with
// XCLAIM, and items any worker held longer than --redis-claim-timeout-s, with XAUTOCLAIM), renders each
// sample range
// into a partial film, uploads it under its range, acknowledges the item and notifies the coordinator.
// It checks the render's cancel key between tiles, so a cancel stops it within the item. The renderer of
// the last render is kept for its next items; its map comes through a MapFetcher, its meshes' files
// through a BundleFetcher (never from this server's --data-dir or assets). Items render in a
// JobArena, at --render-priority like local renders.
#include <atomic>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

#include "api/render_request.hpp"
#include "engine/render/renderer.hpp"
#include "server/app.hpp"
#include "server/scale_out/bundle_fetcher.hpp"
#include "server/scale_out/map_fetcher.hpp"
#include "server/scale_out/redis_client.hpp"
#include "server/scale_out/worker_heartbeat.hpp"

namespace lp::server {

class RenderWorker {
 public:
  // Starts the thread; `consumer` names this worker in the consumer group (host and process id).
  RenderWorker(App& app, std::string consumer);
  ~RenderWorker();  // stops at the next tile; an unfinished item goes to another worker
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

 private:
  struct Loaded {  // a render's renderer, with the request whose models it uses
    std::string id;
    api::RenderRequest request;
    std::unique_ptr<render::Renderer> renderer;
  };

  void loop(const std::stop_token& stop);
  std::optional<StreamEntry> next_item();
  void take(const StreamEntry& item, const std::stop_token& stop);
  render::Renderer* renderer_for(const std::string& id);  // nullptr when the render is gone
  bool render(const std::string& id, render::SampleRange range, const std::stop_token& stop);

  App& app_;
  const std::string consumer_;
  RedisClient redis_;
  RedisClient cancel_check_;  // asked from render threads between tiles
  MapFetcher maps_;
  BundleFetcher bundles_;
  std::optional<Loaded> loaded_;
  WorkerHeartbeat heartbeat_;  // outlives the thread: a stopped worker's items go to others at once
  std::jthread thread_;
};

// "host-pid": a consumer name for this process.
std::string worker_name();

}  // namespace lp::server
