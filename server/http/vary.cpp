#include "server/http/vary.hpp"

#include <string>

namespace lp::server {

void add_vary(httplib::Response& res, std::string_view field) {
  const std::string vary = res.get_header_value("Vary");
  if (vary.find(field) != std::string::npos) return;
  res.headers.erase("Vary");
  res.set_header("Vary", vary.empty() ? std::string(field) : vary + ", " + std::string(field));
}

}  // namespace lp::server
