#pragma once
// Client input quoted in error messages, bounded: a message names what was wrong without growing with
// the input (a 200 KB string is cut, an array or object is described by its size, never dumped).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace lp::api {

inline constexpr size_t kExcerptBytes = 64;

// `text` if it is at most kExcerptBytes long, else its first bytes (never half a UTF-8 character) and "...".
std::string excerpt(std::string_view text);

// A JSON value for a message: a scalar as JSON text (excerpted), an array or object by its kind and size.
std::string describe(const nlohmann::json& value);

}  // namespace lp::api
