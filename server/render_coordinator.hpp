#pragma once
// The coordinator's side of a render split over machines: puts the render's description and its work
// items (sample ranges of --redis-item-spp samples per pixel) on Redis, then merges the partial films
// workers upload as their notices arrive, each range once, into one partial film of the whole render.
// A cancel (or a stop) tells the workers through the cancel key and removes the render's items.
#include <functional>
#include <string>
#include <vector>

#include "engine/render/partial_film.hpp"
#include "engine/render/scene_desc.hpp"
#include "server/redis_client.hpp"
#include "server/render_description.hpp"
#include "server/scale_out.hpp"

namespace lp::server {

// The ranges of `per_item` samples per pixel (the last takes the remainder) that make up `spp`.
std::vector<render::SampleRange> work_items(int spp, int per_item);

class RenderCoordinator {
 public:
  RenderCoordinator(const ScaleOut& scale_out, std::string render_id);

  // After each merged range: the merged film, the range that arrived and the rays it took.
  using OnMerged =
      std::function<void(const render::PartialFilm& merged, render::SampleRange range, uint64_t rays)>;
  // Returns true once every range is merged; false when `stop()` became true (checked at least twice a
  // second). Throws RedisError when Redis stays unreachable, std::runtime_error with a worker's message
  // when a worker could not render an item.
  bool run(const RenderDescription& description, const render::RenderSettings& settings,
           const std::function<bool()>& stop, const OnMerged& on_merged);

 private:
  void publish(const RenderDescription& description, const std::vector<render::SampleRange>& items);
  void withdraw();  // removes the render's keys (after telling workers to stop, on a cancel)

  const ScaleOut scale_out_;
  const std::string id_;
  RedisClient redis_;
};

}  // namespace lp::server
