#include "server/render_coordinator.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <set>
#include <span>
#include <stdexcept>

#include "engine/render/partial_film_codec.hpp"
#include "server/render_keys.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;
namespace keys = render_keys;

constexpr auto kNoticeWait = 500ms;
constexpr int kCancelKeyLifetimeS = 3600;  // longer than any item a worker may still be rendering

}  // namespace

std::vector<render::SampleRange> work_items(int spp, int per_item) {
  std::vector<render::SampleRange> out;
  for (int first = 0; first < spp; first += per_item)
    out.push_back({uint32_t(first), uint32_t(std::min(spp, first + per_item))});
  return out;
}

RenderCoordinator::RenderCoordinator(const ScaleOut& scale_out, std::string render_id)
    : scale_out_(scale_out), id_(std::move(render_id)), redis_(scale_out.redis) {}

void RenderCoordinator::publish(const RenderDescription& description,
                                const std::vector<render::SampleRange>& items) {
  redis_.del(
      {keys::items(id_), keys::partials(id_), keys::done(id_), keys::cancel(id_)});  // an earlier run's
  redis_.set(keys::job(id_), description_json(description));
  redis_.xgroup_create(keys::items(id_), keys::kGroup);
  for (const auto& r : items)
    redis_.xadd(keys::items(id_), {{"first", std::to_string(r.first)}, {"end", std::to_string(r.end)}});
  redis_.sadd(keys::kActive, id_);
}

void RenderCoordinator::withdraw() {
  redis_.srem(keys::kActive, id_);
  redis_.del({keys::job(id_), keys::items(id_), keys::partials(id_), keys::done(id_)});
}

bool RenderCoordinator::run(const RenderDescription& description, const render::RenderSettings& settings,
                            const std::function<bool()>& stop, const OnMerged& on_merged) {
  const auto items = work_items(settings.spp, scale_out_.item_spp);
  publish(description, items);
  spdlog::info("render {}: {} work items of {} spp on {}", id_, items.size(), scale_out_.item_spp,
               scale_out_.redis.url());
  render::PartialFilm merged(settings.width, settings.height);
  std::set<std::string> arrived;
  std::string last_notice = "0-0";
  const int64_t pixels = int64_t(settings.width) * settings.height;
  while (arrived.size() < items.size()) {
    if (stop()) {
      redis_.set(keys::cancel(id_), "1", kCancelKeyLifetimeS);
      withdraw();
      return false;
    }
    for (const StreamEntry& notice : redis_.xread(keys::done(id_), last_notice, kNoticeWait)) {
      last_notice = notice.id;
      const std::string field = notice.field("range").value_or("");
      if (const auto error = notice.field("error")) {
        withdraw();
        throw std::runtime_error(fmt::format("a worker could not render samples {}: {}", field, *error));
      }
      if (arrived.contains(field)) continue;  // a duplicate delivery
      const auto bytes = redis_.hget(keys::partials(id_), field);
      if (!bytes) continue;  // workers upload before they notify: only a Redis that lost writes gets here
      const auto partial = render::decode_partial(
          std::span(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size()), pixels);
      if (keys::range_field(partial.range) != field)
        throw std::runtime_error("a partial film under another range");
      merged.merge(partial.film);
      arrived.insert(field);
      redis_.hdel(keys::partials(id_), field);
      on_merged(merged, partial.range, partial.rays);
    }
  }
  withdraw();
  return true;
}

}  // namespace lp::server
