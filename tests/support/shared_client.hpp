#pragma once
// One client of the shared server (test::shared_server) per test binary, and a GET through it.
#include <httplib.h>

#include <string>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp::test {

inline httplib::Client& shared_client() {
  static auto c = shared_server().client();
  return *c;
}

inline Reply shared_get(const std::string& path) {
  return reply(shared_client().Get(path.c_str()));
}

}  // namespace lp::test
