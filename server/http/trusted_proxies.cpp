#include "server/http/trusted_proxies.hpp"

#include <arpa/inet.h>

#include <charconv>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace lp::server {
namespace {

using Address = std::array<uint8_t, 16>;
constexpr int kMappedPrefixBits = 96;  // ::ffff:0:0/96 holds IPv4 addresses

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// The address as 16 bytes and whether it was written as IPv4.
std::optional<std::pair<Address, bool>> parse_address(std::string_view text) {
  const std::string s(text);
  Address a{};
  in_addr v4{};
  if (inet_pton(AF_INET, s.c_str(), &v4) == 1) {
    a[10] = a[11] = 0xff;
    std::memcpy(a.data() + 12, &v4, 4);
    return std::pair{a, true};
  }
  in6_addr v6{};
  if (inet_pton(AF_INET6, s.c_str(), &v6) == 1) {
    std::memcpy(a.data(), &v6, 16);
    return std::pair{a, false};
  }
  return std::nullopt;
}

bool in_network(const Address& a, const Address& network, int bits) {
  for (int i = 0; i < 16 && bits > 0; ++i, bits -= 8) {
    const uint8_t mask = bits >= 8 ? 0xff : uint8_t(0xff << (8 - bits));
    if ((a[size_t(i)] & mask) != (network[size_t(i)] & mask)) return false;
  }
  return true;
}

}  // namespace

void TrustedProxies::add(std::string_view text) {
  const auto bad = [&] {
    return std::invalid_argument("--trusted-proxy takes an IPv4 or IPv6 address or ADDR/BITS, got '" +
                                 std::string(text) + "'");
  };
  const size_t slash = text.find('/');
  const auto address = parse_address(text.substr(0, slash));
  if (!address) throw bad();
  const int max_bits = address->second ? 32 : 128;
  int bits = max_bits;
  if (slash != std::string_view::npos) {
    const std::string_view b = text.substr(slash + 1);
    const auto [end, error] = std::from_chars(b.data(), b.data() + b.size(), bits);
    if (b.empty() || error != std::errc() || end != b.data() + b.size() || bits < 0 || bits > max_bits)
      throw bad();
  }
  networks_.push_back({address->first, address->second ? bits + kMappedPrefixBits : bits});
}

bool TrustedProxies::contains(std::string_view ip) const {
  const auto address = parse_address(ip);
  if (!address) return false;
  for (const Network& n : networks_)
    if (in_network(address->first, n.address, n.bits)) return true;
  return false;
}

std::string TrustedProxies::client_of(const std::string& peer, std::string_view forwarded_for) const {
  if (!contains(peer)) return peer;
  std::string_view rest = forwarded_for;
  while (!trim(rest).empty()) {
    const size_t comma = rest.rfind(',');
    const std::string_view hop = trim(comma == std::string_view::npos ? rest : rest.substr(comma + 1));
    if (!parse_address(hop)) return peer;
    if (!contains(hop)) return std::string(hop);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(0, comma);
  }
  return peer;
}

}  // namespace lp::server
