#include "server/redis_reply.hpp"

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

std::vector<StreamEntry> claimed_entries(const std::string& stream, const RedisReply& reply) {
  std::vector<StreamEntry> out;
  if (reply.type == RedisReply::Type::Array && reply.elements.size() >= 2)
    add_entries(stream, reply.elements[1], out);
  return out;
}

}  // namespace lp::server
