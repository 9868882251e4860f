#include "api/params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "api/api_error.hpp"
#include "api/excerpt.hpp"
#include "engine/core/limits.hpp"

namespace lp::api {
namespace {

std::string field_name(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "." + name;
}

double parse_double(const std::string& field, const std::string& text) {
  try {
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw invalid_field(field, fmt::format("'{}' is not a finite number", excerpt(text)));
}

void check_range(const std::string& field, double v, double min, double max) {
  if (v < min || v > max)
    throw invalid_field(field, fmt::format("{}, got {}", range_message(Range<double>{min, max}), v));
}

int64_t parse_int(const std::string& field, const std::string& text) {
  try {
    size_t used = 0;
    const long long v = std::stoll(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw invalid_field(field, fmt::format("'{}' is not an integer", excerpt(text)));
}

void check_int_range(const std::string& field, int64_t v, int64_t min, int64_t max) {
  if (v < min || v > max)
    throw invalid_field(field, fmt::format("{}, got {}", range_message(Range<int64_t>{min, max}), v));
}

}  // namespace

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
  return out;
}

std::optional<std::string> query_string(const Query& q, const std::string& name) {
  auto it = q.find(name);
  if (it == q.end()) return std::nullopt;
  return it->second;
}

double query_double(const Query& q, const std::string& name, double fallback, double min, double max) {
  return query_optional_double(q, name, min, max).value_or(fallback);
}

std::optional<double> query_optional_double(const Query& q, const std::string& name, double min, double max) {
  const auto text = query_string(q, name);
  if (!text || text->empty()) return std::nullopt;
  const double v = parse_double(name, *text);
  check_range(name, v, min, max);
  return v;
}

int64_t query_int(const Query& q, const std::string& name, int64_t fallback, int64_t min, int64_t max) {
  const auto text = query_string(q, name);
  if (!text || text->empty()) return fallback;
  const int64_t v = parse_int(name, *text);
  check_int_range(name, v, min, max);
  return v;
}

bool query_bool(const Query& q, const std::string& name, bool fallback) {
  const auto text = query_string(q, name);
  if (!text || text->empty()) return fallback;
  if (*text == "true" || *text == "1") return true;
  if (*text == "false" || *text == "0") return false;
  throw invalid_field(name, fmt::format("'{}' is not a boolean (true or false)", excerpt(*text)));
}

std::string query_enum(const Query& q, const std::string& name, const std::string& fallback,
                       const std::vector<std::string>& allowed) {
  const auto text = query_string(q, name);
  if (!text || text->empty()) return fallback;
  for (const auto& a : allowed)
    if (*text == a) return a;
  throw invalid_field(name, fmt::format("'{}' is not one of: {}", excerpt(*text), join(allowed, ", ")));
}

Json parse_json(std::string_view text, std::string_view what) {
  // Called as each array or object opens, before its contents are read: a too-deep document is
  // refused after at most kMaxJsonDepth levels were built.
  const auto bound_depth = [what](int depth, Json::parse_event_t event, Json&) {
    const bool opens =
        event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start;
    if (opens && depth >= kMaxJsonDepth)
      throw ApiError(
          ErrorCode::JsonTooDeep,
          fmt::format("{} nests arrays and objects deeper than the limit of {} levels", what, kMaxJsonDepth));
    return true;
  };
  Json j = Json::parse(text, bound_depth, false);
  if (j.is_discarded()) throw ApiError(ErrorCode::InvalidJson, fmt::format("{} is not valid JSON", what));
  return j;
}

Json parse_json_object(std::string_view body) {
  Json j = parse_json(body);
  if (!j.is_object()) throw ApiError(ErrorCode::InvalidJson, "the request body must be a JSON object");
  return j;
}

Json parse_optional_json_object(std::string_view body) {
  const bool empty = std::all_of(body.begin(), body.end(), [](unsigned char c) { return std::isspace(c); });
  return empty ? Json::object() : parse_json_object(body);
}

void reject_unknown_fields(const Json& body, const std::vector<std::string>& known,
                           const std::string& prefix) {
  const std::set<std::string> names(known.begin(), known.end());
  for (const auto& [key, value] : body.items())
    if (!names.count(key))
      throw invalid_field(field_name(prefix, key),
                          "unknown field (expected one of: " + join(known, ", ") + ")");
}

int64_t json_int(const Json& body, const std::string& name, int64_t fallback, int64_t min, int64_t max,
                 const std::string& prefix) {
  auto it = body.find(name);
  if (it == body.end() || it->is_null()) return fallback;
  const std::string field = field_name(prefix, name);
  int64_t v;
  if (it->is_number_integer()) {
    v = it->get<int64_t>();
  } else if (it->is_number_float() && std::isfinite(it->get<double>()) &&
             std::trunc(it->get<double>()) == it->get<double>() && std::abs(it->get<double>()) < 9e15) {
    v = int64_t(it->get<double>());
  } else {
    throw invalid_field(field, fmt::format("must be an integer, got {}", describe(*it)));
  }
  check_int_range(field, v, min, max);
  return v;
}

double json_double(const Json& body, const std::string& name, double fallback, double min, double max,
                   const std::string& prefix) {
  auto it = body.find(name);
  if (it == body.end() || it->is_null()) return fallback;
  const std::string field = field_name(prefix, name);
  if (!it->is_number()) throw invalid_field(field, fmt::format("must be a number, got {}", describe(*it)));
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw invalid_field(field, "must be finite");
  check_range(field, v, min, max);
  return v;
}

bool json_bool(const Json& body, const std::string& name, bool fallback, const std::string& prefix) {
  auto it = body.find(name);
  if (it == body.end() || it->is_null()) return fallback;
  if (!it->is_boolean())
    throw invalid_field(field_name(prefix, name),
                        fmt::format("must be true or false, got {}", describe(*it)));
  return it->get<bool>();
}

std::string json_string(const Json& body, const std::string& name, const std::optional<std::string>& fallback,
                        const std::string& prefix) {
  auto it = body.find(name);
  const std::string field = field_name(prefix, name);
  if (it == body.end() || it->is_null()) {
    if (fallback) return *fallback;
    throw invalid_field(field, "is required");
  }
  if (!it->is_string()) throw invalid_field(field, fmt::format("must be a string, got {}", describe(*it)));
  return it->get<std::string>();
}

std::string json_enum(const Json& body, const std::string& name, const std::string& fallback,
                      const std::vector<std::string>& allowed, const std::string& prefix) {
  const std::string v = json_string(body, name, fallback, prefix);
  for (const auto& a : allowed)
    if (v == a) return v;
  throw invalid_field(field_name(prefix, name),
                      fmt::format("'{}' is not one of: {}", excerpt(v), join(allowed, ", ")));
}

}  // namespace lp::api
