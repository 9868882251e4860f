#include "server/http/request_context.hpp"

#include <atomic>

namespace lp::server {
namespace {

std::atomic<int64_t> in_flight{0};

}  // namespace

RequestContext& current_request() {
  thread_local RequestContext context;
  return context;
}

void begin_request_context(std::string accept_encoding, std::string client) {
  RequestContext& r = current_request();
  static std::atomic<uint64_t> arrivals{0};
  r.start = std::chrono::steady_clock::now();
  r.arrival = arrivals.fetch_add(1, std::memory_order_relaxed);
  r.id.clear();
  r.client = std::move(client);
  r.route.clear();
  r.accept_encoding = std::move(accept_encoding);
  r.caching = Caching::None;
  r.if_none_match.clear();
  in_flight.fetch_add(1, std::memory_order_relaxed);
}

void end_request_context() {
  in_flight.fetch_sub(1, std::memory_order_relaxed);
}

int64_t requests_in_flight() {
  return in_flight.load(std::memory_order_relaxed);
}

}  // namespace lp::server
