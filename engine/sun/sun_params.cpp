#include "engine/sun/sun_params.hpp"

#include <fmt/format.h>

#include "engine/core/validate.hpp"

namespace lp {

void SunParams::validate(const std::string& prefix) const {
  for (const SunField& f : kSunFields) require_in(field_path(prefix, f.name), this->*f.member, f.range);
}

std::string SunParams::key() const {
  std::string out;
  for (const SunField& f : kSunFields)
    out += fmt::format("{}{}={}", out.empty() ? "" : ";", f.name, this->*f.member);
  return out;
}

}  // namespace lp
