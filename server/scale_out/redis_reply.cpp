#include "server/scale_out/redis_reply.hpp"

#include <charconv>
#include <cstdint>
#include <utility>

namespace lp::server {
namespace {

bool is_array(const RedisReply& r, size_t size) {
  return r.type == RedisReply::Type::Array && r.elements.size() == size;
}

// [id, [field, value, ...]] of `stream`; nullopt for an entry deleted meanwhile.
std::optional<StreamEntry> entry(const std::string& stream, const RedisReply& r) {
  if (!is_array(r, 2) || r.elements[1].type != RedisReply::Type::Array) return std::nullopt;
  StreamEntry out{stream, r.elements[0].text, {}};
  const auto& fields = r.elements[1].elements;
  for (size_t i = 0; i + 1 < fields.size(); i += 2) out.fields[fields[i].text] = fields[i + 1].text;
  return out;
}

void add_entries(const std::string& stream, const RedisReply& list, std::vector<StreamEntry>& out) {
  for (const RedisReply& r : list.elements)
    if (auto e = entry(stream, r)) out.push_back(std::move(*e));
}

// "MS-SEQ" as a pair; (0, 0) when it does not parse.
std::pair<uint64_t, uint64_t> parse_stream_id(const std::string& id) {
  uint64_t ms = 0, seq = 0;
  const char* end = id.data() + id.size();
  const auto [p, ec] = std::from_chars(id.data(), end, ms);
  if (ec != std::errc() || p == end || *p != '-') return {0, 0};
  const auto [q, ec2] = std::from_chars(p + 1, end, seq);
  if (ec2 != std::errc() || q != end) return {0, 0};
  return {ms, seq};
}

}  // namespace

std::optional<std::string> StreamEntry::field(const std::string& name) const {
  const auto it = fields.find(name);
  return it == fields.end() ? std::nullopt : std::optional(it->second);
}

std::vector<StreamEntry> stream_entries(const RedisReply& reply) {
  std::vector<StreamEntry> out;
  for (const RedisReply& s : reply.elements)
    if (is_array(s, 2)) add_entries(s.elements[0].text, s.elements[1], out);
  return out;
}

bool stream_id_less(const std::string& a, const std::string& b) {
  return parse_stream_id(a) < parse_stream_id(b);
}

std::vector<StreamEntry> range_entries(const std::string& stream, const RedisReply& reply) {
  std::vector<StreamEntry> out;
  add_entries(stream, reply, out);
  return out;
}

std::vector<std::string> pending_ids(const RedisReply& reply) {
  std::vector<std::string> out;
  for (const RedisReply& r : reply.elements)
    if (r.type == RedisReply::Type::Array && !r.elements.empty()) out.push_back(r.elements[0].text);
  return out;
}

std::vector<PendingItem> pending_items(const RedisReply& reply) {
  std::vector<PendingItem> out;
  for (const RedisReply& r : reply.elements)
    if (r.type == RedisReply::Type::Array && r.elements.size() >= 2)
      out.push_back({r.elements[0].text, r.elements[1].text});
  return out;
}

std::optional<std::string> group_field(const RedisReply& reply, const std::string& group,
                                       const std::string& field) {
  for (const RedisReply& g : reply.elements) {
    std::map<std::string, const RedisReply*> fields;
    for (size_t i = 0; i + 1 < g.elements.size(); i += 2) fields[g.elements[i].text] = &g.elements[i + 1];
    const auto name = fields.find("name"), wanted = fields.find(field);
    if (name == fields.end() || name->second->text != group || wanted == fields.end()) continue;
    const RedisReply& v = *wanted->second;
    return v.type == RedisReply::Type::Integer ? std::to_string(v.integer) : v.text;
  }
  return std::nullopt;
}

std::vector<StreamEntry> claimed_entries(const std::string& stream, const RedisReply& reply) {
  std::vector<StreamEntry> out;
  if (reply.type == RedisReply::Type::Array && reply.elements.size() >= 2)
    add_entries(stream, reply.elements[1], out);
  return out;
}

}  // namespace lp::server
