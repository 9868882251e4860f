// What a worker and a coordinator read from Redis, on any bytes of the Redis protocol: the reply as a
// connection reads it, the stream entries, pending ids and group fields the stream commands' replies
// hold, the sample ranges of work items and notices, and a render's description. Each either yields a
// value or refuses with std::invalid_argument; nothing else may escape.
// fuzz-dictionary: redis_reply.dict
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "server/scale_out/redis_client.hpp"
#include "server/scale_out/redis_keys.hpp"
#include "server/scale_out/render_description.hpp"

namespace {

void read_entries(const std::vector<lp::server::StreamEntry>& entries) {
  for (const auto& e : entries) {
    (void)lp::server::render_keys::parse_range(e.field("first").value_or("") + "-" +
                                               e.field("end").value_or(""));
    (void)lp::server::render_keys::parse_range(e.field("range").value_or(""));
    (void)lp::server::render_keys::id_of_items(e.stream);
    (void)lp::server::stream_id_less(e.id, "1-0");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace lp::server;
  const auto reply = parse_reply(lp::fuzz::as_text(data, size));
  if (!reply) return 0;
  read_entries(stream_entries(*reply));
  read_entries(claimed_entries("lightprobe:render:x:items", *reply));
  read_entries(range_entries("lightprobe:render:x:items", *reply));
  for (const auto& id : pending_ids(*reply)) (void)stream_id_less(id, "0-0");
  (void)group_field(*reply, "workers", "last-delivered-id");
  try {
    (void)parse_description(reply->text);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
