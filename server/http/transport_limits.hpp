#pragma once
// What clients may hold of the transport: connections (all together and from one address), the time a
// request's head, a body read or a response write, and an idle keep-alive connection may take, and a
// request body's size, and whose word says which client a request is from. The flags that set them are
// declared here.
#include <chrono>
#include <cstdint>

#include "api/parameters.hpp"
#include "server/http/trusted_proxies.hpp"

namespace lp::server {

inline constexpr api::IntParameter kMaxUploadMb{"max-upload-mb", 512,
                                                {1, 1 << 20},    "largest request body in MiB",
                                                nullptr,         api::ErrorCode::PayloadTooLarge};
inline constexpr api::IntParameter kMaxConnections{
    "max-connections", 1024, {1, 1 << 20}, "open connections at once; more are refused with 503"};
inline constexpr api::IntParameter kMaxConnectionsPerClient{
    "max-connections-per-client",
    512,
    {1, 1 << 20},
    "open connections from one client address, or requests in flight from one client behind a\n"
    "--trusted-proxy; more are refused with 503"};
inline constexpr api::IntParameter kHeaderTimeoutS{
    "header-timeout-s", 10, {1, 3600}, "seconds for a request line and its headers to arrive; then 408"};
inline constexpr api::IntParameter kIoTimeoutS{
    "io-timeout-s",
    30,
    {1, 3600},
    "seconds a body read or a response write may wait; then the connection closes"};
inline constexpr api::IntParameter kKeepAliveTimeoutS{
    "keep-alive-timeout-s", 5, {1, 3600}, "seconds an idle keep-alive connection stays open"};

struct TransportLimits {
  int max_connections = int(kMaxConnections.fallback);
  int max_connections_per_client = int(kMaxConnectionsPerClient.fallback);
  // from the start of a request to the end of its head
  std::chrono::seconds header_timeout{kHeaderTimeoutS.fallback};
  std::chrono::seconds io_timeout{kIoTimeoutS.fallback};  // longest wait of a body read or a response write
  std::chrono::seconds keep_alive_timeout{kKeepAliveTimeoutS.fallback};  // idle time between requests
  uint64_t max_body = uint64_t(kMaxUploadMb.fallback) << 20;             // bytes
  TrustedProxies trusted_proxies;  // --trusted-proxy: whose X-Forwarded-For names the client
};

}  // namespace lp::server
