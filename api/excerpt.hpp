#pragma once
// Bounded quotations of client input for error messages: a message names what was wrong without
// growing with the input (a 200 KB value or a 100,000-level nesting is described, never dumped).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace lp::api {

inline constexpr size_t kExcerptBytes = 48;

// `text` when it is at most kExcerptBytes long, else its first bytes (cut on a UTF-8 boundary) and "...".
std::string excerpt(std::string_view text);

// A short description of a JSON value: scalars as JSON (strings excerpted), containers by their size
// ("an array of 3 items", "an object with 2 members").
std::string describe(const nlohmann::json& value);

}  // namespace lp::api
