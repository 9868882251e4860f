#include "api/fresnel_request.hpp"

#include <fmt/format.h>

#include <limits>

#include "api/api_error.hpp"
#include "api/parameters.hpp"

namespace lp::api {
namespace {

bool given(const Query& q, const std::string& name) {
  return query_string(q, name).value_or("") != "";
}

// A finite number in [min, max], with a plain "must be > 0" for the non-positive values of indices.
double number(const Query& q, const std::string& name, std::optional<double> fallback, double min,
              double max) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::optional<double> v = query_optional_double(q, name, -kInf, kInf);
  if (!v) {
    if (fallback) return *fallback;
    throw invalid_field(name, "is required");
  }
  if (min > 0 && *v <= 0) throw invalid_field(name, fmt::format("{} must be > 0", *v));
  if (*v < min || *v > max)
    throw invalid_field(name, fmt::format("{}, got {}", range_message(Range<double>{min, max}), *v));
  return *v;
}

double refractive_index(const Query& q, const std::string& name,
                        std::optional<double> fallback = std::nullopt) {
  return number(q, name, fallback, limits::kFresnelIndex.min, limits::kFresnelIndex.max);
}

ConductorSpec parse_conductor(const Query& q) {
  ConductorSpec c;
  if (given(q, "metal")) {
    if (given(q, "eta")) throw invalid_field("eta", "give either 'metal' or 'eta' and 'k', not both");
    if (given(q, "k")) throw invalid_field("k", "give either 'metal' or 'eta' and 'k', not both");
    const ConductorPreset& m = lookup_metal(query_enum(q, "metal", "", metal_names()));
    c.metal = std::string(m.name);
    c.eta = m.eta;
    c.k = m.k;
    return c;
  }
  if (!given(q, "eta")) throw invalid_field("eta", "is required with 'k' (or give 'metal')");
  if (!given(q, "k")) throw invalid_field("k", "is required with 'eta' (0 for a dielectric)");
  const double eta = refractive_index(q, "eta");
  const double k =
      number(q, "k", std::nullopt, limits::kFresnelExtinction.min, limits::kFresnelExtinction.max);
  c.eta = {eta, eta, eta};
  c.k = {k, k, k};
  return c;
}

}  // namespace

FresnelRequest parse_fresnel_query(const Query& q) {
  FresnelRequest r;
  r.csv = query_enum(q, "format", TableFormat::JsonDocument) == TableFormat::Csv;
  r.step =
      number(q, kFresnelStep.name, kFresnelStep.fallback, kFresnelStep.range.min, kFresnelStep.range.max);
  r.eta_i = refractive_index(q, "eta_i", 1.0);
  const bool conductor = given(q, "metal") || given(q, "eta") || given(q, "k");
  if (conductor) {
    if (given(q, "eta_t"))
      throw invalid_field("eta_t", "is for dielectric tables; not allowed with 'metal', 'eta' or 'k'");
    r.conductor = parse_conductor(q);
  } else {
    if (!given(q, "eta_t"))
      throw invalid_field("eta_t", "is required (or give 'metal', or 'eta' and 'k' for a conductor)");
    r.eta_t = refractive_index(q, "eta_t");
  }
  return r;
}

}  // namespace lp::api
