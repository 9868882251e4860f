#pragma once
// What every request-parser fuzz target shares: the input as a request body or a query string, and the
// property every rejection must have (a 4xx ApiError with a short message). Anything else a parser
// throws escapes LLVMFuzzerTestOneInput, and libFuzzer reports it as a crash (the server would answer 500).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "api/api_error.hpp"
#include "api/params.hpp"

namespace lp::fuzz {

// Longest message a rejection may carry: field paths and lists of allowed names fit, echoed input does not.
inline constexpr size_t kMaxMessageBytes = 1024;

inline std::string as_text(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// "a=1&b=x" as the server's decoded query parameters; a pair without '=' has an empty value.
inline api::Query as_query(const std::string& text) {
  api::Query q;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('&', start);
    if (end == std::string::npos) end = text.size();
    const std::string pair = text.substr(start, end - start);
    const size_t eq = pair.find('=');
    q.emplace(pair.substr(0, eq), eq == std::string::npos ? "" : pair.substr(eq + 1));
    start = end + 1;
  }
  return q;
}

inline void check_rejection(const api::ApiError& e) {
  const std::string message = e.what();
  if (e.status() >= 400 && e.status() < 500 && message.size() <= kMaxMessageBytes) return;
  std::fprintf(stderr, "bad rejection: status %d, code %s, %zu-byte message: %.300s\n", e.status(),
               std::string(api::code_name(e.code())).c_str(), message.size(), message.c_str());
  std::abort();
}

}  // namespace lp::fuzz
