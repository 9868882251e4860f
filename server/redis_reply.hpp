#pragma once
// A Redis reply as a plain value (copied out of hiredis's reply), and the stream entries of the replies of
// XREADGROUP, XREAD and XAUTOCLAIM.
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

// [[stream, [[id, [field, value, ...]], ...]], ...] (XREAD, XREADGROUP); nothing for nil.
std::vector<StreamEntry> stream_entries(const RedisReply& reply);
// [next, [[id, [field, value, ...]], ...], deleted] (XAUTOCLAIM) for `stream`; entries deleted from the
// stream meanwhile (nil fields) are left out.
std::vector<StreamEntry> claimed_entries(const std::string& stream, const RedisReply& reply);

}  // namespace lp::server
