#pragma once
// The Redis keys of renders split over machines, and the form of a sample range in them ("FIRST-END").
//   lightprobe:renders            set of the ids of renders with work items out
//   lightprobe:render:ID:job      the render's description for workers (render_description.hpp)
//   lightprobe:render:ID:items    stream of work items {first, end}, consumer group "workers"
//   lightprobe:render:ID:partials hash of the partial films that arrived, by range
//   lightprobe:render:ID:done     stream of notices {range, rays} or {range, error} from workers
//   lightprobe:render:ID:cancel   set when the render is cancelled; workers check it between tiles
//   lightprobe:worker:NAME        a worker's heartbeat, set while it lives (worker_heartbeat.hpp)
#include <charconv>
#include <optional>
#include <string>
#include <string_view>

#include "engine/render/partial_film.hpp"

namespace lp::server::render_keys {

inline constexpr const char* kActive = "lightprobe:renders";
inline constexpr const char* kGroup = "workers";
inline constexpr const char* kPrefix = "lightprobe:render:";

inline std::string key(const std::string& id, const char* what) {
  return kPrefix + id + ":" + what;
}
inline std::string job(const std::string& id) {
  return key(id, "job");
}
inline std::string items(const std::string& id) {
  return key(id, "items");
}
inline std::string partials(const std::string& id) {
  return key(id, "partials");
}
inline std::string done(const std::string& id) {
  return key(id, "done");
}
inline std::string cancel(const std::string& id) {
  return key(id, "cancel");
}

inline std::string heartbeat(const std::string& consumer) {
  return "lightprobe:worker:" + consumer;
}

// The render id of an items stream's key; empty if it is not one.
inline std::string id_of_items(const std::string& stream) {
  const std::string_view prefix = kPrefix, suffix = ":items";
  if (stream.size() <= prefix.size() + suffix.size() || !stream.starts_with(prefix) ||
      !stream.ends_with(suffix))
    return "";
  return stream.substr(prefix.size(), stream.size() - prefix.size() - suffix.size());
}

inline std::string range_field(render::SampleRange r) {
  return std::to_string(r.first) + "-" + std::to_string(r.end);
}

inline std::optional<render::SampleRange> parse_range(const std::string& text) {
  render::SampleRange r;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, r.first);
  if (ec != std::errc() || p == end || *p != '-') return std::nullopt;
  auto [q, ec2] = std::from_chars(p + 1, end, r.end);
  if (ec2 != std::errc() || q != end || r.end <= r.first) return std::nullopt;
  return r;
}

}  // namespace lp::server::render_keys
