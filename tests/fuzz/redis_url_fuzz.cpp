// The --redis URL parser, on any text: std::invalid_argument is a clean refusal; a parsed address prints
// back to a URL that parses to the same address.
// fuzz-dictionary: redis_url.dict
#include <cstdlib>
#include <stdexcept>

#include "fuzz_input.hpp"
#include "server/scale_out/redis_url.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto address = lp::server::parse_redis_url(lp::fuzz::as_text(data, size));
    const auto again = lp::server::parse_redis_url(address.url());
    if (again.host != address.host || again.port != address.port) std::abort();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
