#pragma once
// A Redis reply as a plain value (copied out of hiredis's reply), and what the replies of the stream
// commands hold: entries (XREADGROUP, XREAD, XAUTOCLAIM, XRANGE), pending ids (XPENDING) and a consumer
// group's fields (XINFO GROUPS). Malformed parts of a reply are left out, never trusted.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lp::server {

struct RedisReply {
  enum class Type { Nil, Integer, String, Status, Array };
  Type type = Type::Nil;
  long long integer = 0;
  std::string text;  // a string's bytes (binary safe) or a status
  std::vector<RedisReply> elements;

  bool nil() const { return type == Type::Nil; }
};

struct StreamEntry {
  std::string stream;  // the key it was read from
  std::string id;
  std::map<std::string, std::string> fields;
  std::optional<std::string> field(const std::string& name) const;
};

// Whether stream entry id `a` ("MS-SEQ") comes before `b`; an id that does not parse comes first.
bool stream_id_less(const std::string& a, const std::string& b);

// [[stream, [[id, [field, value, ...]], ...]], ...] (XREAD, XREADGROUP); nothing for nil.
std::vector<StreamEntry> stream_entries(const RedisReply& reply);
// [next, [[id, [field, value, ...]], ...], deleted] (XAUTOCLAIM) for `stream`; entries deleted from the
// stream meanwhile (nil fields) are left out.
std::vector<StreamEntry> claimed_entries(const std::string& stream, const RedisReply& reply);
// [[id, [field, value, ...]], ...] (XRANGE) for `stream`.
std::vector<StreamEntry> range_entries(const std::string& stream, const RedisReply& reply);
// [[id, consumer, idle, deliveries], ...] (XPENDING key group - + count): the ids.
std::vector<std::string> pending_ids(const RedisReply& reply);
// [[id, consumer, idle, deliveries], ...] (XPENDING): each id with the consumer holding it.
struct PendingItem {
  std::string id;
  std::string consumer;
};
std::vector<PendingItem> pending_items(const RedisReply& reply);
// [[name, value, ...], ...] (XINFO GROUPS): the value of `field` in the group named `group`, as text.
std::optional<std::string> group_field(const RedisReply& reply, const std::string& group,
                                       const std::string& field);

}  // namespace lp::server
