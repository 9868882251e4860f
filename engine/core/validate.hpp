#pragma once
// Checks for the validate() of engine parameter structs: each failure is an lp::Error(InvalidArgument)
// naming the field by its path, so a caller can report it in its own terms.
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/limits.hpp"
#include "engine/core/vec3.hpp"

namespace lp {

// "prefix.name", or "name" at the top.
inline std::string field_path(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "." + name;
}

[[noreturn]] inline void invalid_parameter(const std::string& field, const std::string& problem) {
  throw Error(ErrorKind::InvalidArgument, field, problem);
}

inline void require(bool ok, const std::string& field, const std::string& problem) {
  if (!ok) invalid_parameter(field, problem);
}

template <class T, class V>
void require_in(const std::string& field, V value, const Range<T>& range) {
  if (!range.contains(T(value)))
    invalid_parameter(field, fmt::format("{}, got {}", range_message(range), value));
}

// Each of the three components in `range`; the field is named per component ("albedo[1]"), or as a
// whole when all three are the same (a grey colour given as one number).
template <class T>
void require_in(const std::string& field, Vec3 v, const Range<T>& range) {
  if (v.x == v.y && v.y == v.z) return require_in(field, v.x, range);
  require_in(field + "[0]", v.x, range);
  require_in(field + "[1]", v.y, range);
  require_in(field + "[2]", v.z, range);
}

}  // namespace lp
