#pragma once
// Validation at the edge: typed, range-checked reads of query parameters and JSON body fields.
// Every failure is an ApiError 400 naming the field and saying what was expected.
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

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

// Deepest nesting of arrays and objects a request body may have (the API needs far fewer levels):
// bounded while parsing, so no later recursion over the value can exhaust the stack.
inline constexpr int kMaxJsonDepth = 64;

// Parses a request body as a JSON object; 400 "invalid_json" if it is not one, 400 "json_too_deep"
// when it nests deeper than kMaxJsonDepth.
Json parse_json_object(const std::string& body);
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

}  // namespace lp::api
