#pragma once
// Validation at the edge: typed, range-checked reads of query parameters and JSON body fields.
// Every failure is an ApiError 400 naming the field and saying what was expected.
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "engine/core/enum_table.hpp"

namespace lp::api {

using Query = std::multimap<std::string, std::string>;  // the shape of httplib::Params
using Json = nlohmann::json;

std::optional<std::string> query_string(const Query& q, const std::string& name);
double query_double(const Query& q, const std::string& name, double fallback, double min, double max);
std::optional<double> query_optional_double(const Query& q, const std::string& name, double min, double max);
int64_t query_int(const Query& q, const std::string& name, int64_t fallback, int64_t min, int64_t max);
bool query_bool(const Query& q, const std::string& name, bool fallback);
std::string query_enum(const Query& q, const std::string& name, const std::string& fallback,
                       const std::vector<std::string>& allowed);

// Deepest nesting of arrays and objects a JSON request body may have (the API needs a few levels). It is
// enforced while parsing, so neither the parse nor any later walk over a value can exhaust the stack.
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text; 400 "invalid_json" if it is not JSON, 400 "json_too_deep" past kMaxJsonDepth levels.
// `what` names the text in those messages.
Json parse_json(std::string_view text, std::string_view what = "the request body");
// As parse_json, and 400 "invalid_json" unless the value is an object.
Json parse_json_object(std::string_view body);
// The same, and an empty (or all white space) body as the empty object: a POST whose fields all have
// defaults.
Json parse_optional_json_object(std::string_view body);
// Fails with 400 naming the first key of `body` not in `known` (catches typos like "cout").
void reject_unknown_fields(const Json& body, const std::vector<std::string>& known,
                           const std::string& prefix = "");

int64_t json_int(const Json& body, const std::string& name, int64_t fallback, int64_t min, int64_t max,
                 const std::string& prefix = "");
double json_double(const Json& body, const std::string& name, double fallback, double min, double max,
                   const std::string& prefix = "");
bool json_bool(const Json& body, const std::string& name, bool fallback, const std::string& prefix = "");
std::string json_string(const Json& body, const std::string& name, const std::optional<std::string>& fallback,
                        const std::string& prefix = "");
std::string json_enum(const Json& body, const std::string& name, const std::string& fallback,
                      const std::vector<std::string>& allowed, const std::string& prefix = "");

std::string join(const std::vector<std::string>& items, const std::string& sep);

// An enum parameter: its allowed names and its parse come from the enum's table (enum_table.hpp).
template <class E>
requires std::is_enum_v<E> E query_enum(const Query& q, const std::string& name, E fallback) {
  return *parse_enum<E>(query_enum(q, name, enum_name(fallback), enum_names<E>()));
}

template <class E>
requires std::is_enum_v<E> E json_enum(const Json& body, const std::string& name, E fallback,
                                       const std::string& prefix = "") {
  return *parse_enum<E>(json_enum(body, name, enum_name(fallback), enum_names<E>(), prefix));
}

}  // namespace lp::api
