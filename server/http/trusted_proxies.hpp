#pragma once
// Which peers speak for other clients: the reverse proxies of --trusted-proxy. A connection from one of
// them is not held to the per-client connection limit (the proxy owns client limits, and many clients
// share its connections); each of its requests is counted instead against the client its
// X-Forwarded-For names. That client is the right-most hop not itself a trusted proxy: hops further left
// were written by the client and could be anything. Without --trusted-proxy, X-Forwarded-For is ignored.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lp::server {

class TrustedProxies {
 public:
  // Adds ADDR or ADDR/BITS (IPv4 or IPv6); throws std::invalid_argument naming the text otherwise.
  void add(std::string_view text);
  bool empty() const { return networks_.empty(); }
  // Whether `ip` (as the transport prints a peer: dotted IPv4, or IPv6 text) lies in a trusted network.
  // An IPv4-mapped IPv6 address counts as its IPv4 address.
  bool contains(std::string_view ip) const;
  // The client a request from `peer` comes from: `peer` unless it is trusted; then the right-most hop of
  // `forwarded_for` (X-Forwarded-For's comma-separated values) that is not trusted, or `peer` when the
  // header names none, or a hop is no address (a proxy that writes the header always writes addresses).
  std::string client_of(const std::string& peer, std::string_view forwarded_for) const;

 private:
  struct Network {
    std::array<uint8_t, 16> address{};  // IPv4 as IPv4-mapped IPv6
    int bits = 128;
  };
  std::vector<Network> networks_;
};

}  // namespace lp::server
