#pragma once
// A server response as plain values (status, body, headers), so tests can keep and compare it.
#include <httplib.h>

#include <nlohmann/json.hpp>
#include <string>

namespace lp::test {

struct Reply {
  int status = 0;  // 0 = no response
  std::string body;
  httplib::Headers headers;

  nlohmann::json body_json() const { return nlohmann::json::parse(body); }
  std::string header(const std::string& name) const {
    auto it = headers.find(name);
    return it == headers.end() ? "" : it->second;
  }
  std::string type() const { return header("Content-Type"); }
};

inline Reply reply(const httplib::Result& res) {
  if (!res) return {};
  return {res->status, res->body, res->headers};
}

}  // namespace lp::test
