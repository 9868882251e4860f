#pragma once
// Which Host names and which origins' pages the server answers besides its own (browser_policy.hpp).
#include <string>
#include <vector>

namespace lp::server {

struct BrowserPolicyConfig {
  std::vector<std::string> allowed_hosts;  // --allowed-host: Host names answered besides loopback and --host
  std::vector<std::string> cors_origins;   // --cors-origin: other origins that may call the API ("*": any)
};

}  // namespace lp::server
