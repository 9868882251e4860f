#include "server/http/request_id.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <random>

#include "engine/core/rng.hpp"

namespace lp::server {
namespace {

bool is_safe_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
         c == '.' || c == ':';
}

uint64_t random_seed() {
  std::random_device device;
  return (uint64_t(device()) << 32) ^ device();
}

}  // namespace

bool is_safe_request_id(std::string_view id) {
  return !id.empty() && id.size() <= kMaxRequestIdLength && std::all_of(id.begin(), id.end(), is_safe_char);
}

std::string new_request_id() {
  thread_local Rng rng(random_seed(), 0);
  return fmt::format("{:016x}", rng.next_u64());
}

std::string request_id_for(const httplib::Request& req) {
  const std::string given = req.get_header_value(kRequestIdHeader);
  return is_safe_request_id(given) ? given : new_request_id();
}

}  // namespace lp::server
