#include "server/request_context.hpp"

namespace lp::server {

RequestContext& current_request() {
  thread_local RequestContext context;
  return context;
}

void begin_request_context(std::string accept_encoding) {
  RequestContext& r = current_request();
  r.start = std::chrono::steady_clock::now();
  r.id.clear();
  r.route.clear();
  r.accept_encoding = std::move(accept_encoding);
  r.caching = Caching::None;
  r.if_none_match.clear();
}

}  // namespace lp::server
