// The --redis URL parser, on any text: std::invalid_argument is a clean refusal; a parsed address prints
// back to a URL that parses to the same address (but for its password, shown as ***).
// fuzz-dictionary: redis_url.dict
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "server/scale_out/redis_url.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto address = lp::server::parse_redis_url(lp::fuzz::as_text(data, size));
    const std::string shown = address.url();
    const auto again = lp::server::parse_redis_url(shown);
    if (again.host != address.host || again.port != address.port || again.tls != address.tls ||
        again.user != address.user || again.db != address.db ||
        again.password.has_value() != address.password.has_value())
      std::abort();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
