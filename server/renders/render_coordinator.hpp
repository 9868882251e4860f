#pragma once
// The coordinator's side of a render split over machines: puts the render's description and its work
// items (sample ranges of at most --redis-item-spp samples per pixel) on Redis, then merges the partial films
// workers upload as their notices arrive, each range once, into one partial film of the whole render.
// Every few seconds it puts back what a Redis that lost writes (restarted without them on disk) lost:
// the description, the consumer group and the items of ranges that are neither waiting, nor held by a
// worker, nor merged. A cancel (or a stop) tells the workers through the cancel key and removes the
// render's items.
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "engine/render/partial_film.hpp"
#include "engine/render/scene_desc.hpp"
#include "server/scale_out/redis_client.hpp"
#include "server/scale_out/render_description.hpp"
#include "server/scale_out/scale_out.hpp"

namespace lp::server {

class RenderCoordinator {
 public:
  RenderCoordinator(const ScaleOut& scale_out, std::string render_id);

  // After each merged range: the merged film, the range that arrived and the rays it took.
  using OnMerged =
      std::function<void(const render::PartialFilm& merged, render::SampleRange range, uint64_t rays)>;
  // Has `items` rendered and merges them into `film` (which may hold ranges an earlier run merged).
  // Returns true once every item is merged; false when `stop()` became true (checked at least twice a
  // second). Throws RedisError when Redis stays unreachable, std::runtime_error with a worker's message
  // when a worker could not render an item.
  bool run(const RenderDescription& description, const std::vector<render::SampleRange>& items,
           render::PartialFilm film, const std::function<bool()>& stop, const OnMerged& on_merged);

 private:
  struct Merged {  // what arrived so far
    render::PartialFilm film;
    std::set<std::string> ranges;
    std::string last_notice = "0-0";
  };

  void publish(const std::vector<render::SampleRange>& items);
  void read_notices(Merged& merged, std::chrono::milliseconds wait, const OnMerged& on_merged);
  bool merge(const std::string& range, Merged& merged, const OnMerged& on_merged);
  void restore(const std::vector<render::SampleRange>& items, Merged& merged, const OnMerged& on_merged);
  void withdraw();  // removes the render's keys (after telling workers to stop, on a cancel)

  const ScaleOut scale_out_;
  const std::string id_;
  RedisClient redis_;
  std::string description_;  // as stored for workers
};

}  // namespace lp::server
