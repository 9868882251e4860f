#pragma once
// GET /api/v1/fresnel query: a dielectric pair (eta_i, eta_t) or a conductor (metal=NAME, or eta and k
// for all three channels) seen from a medium eta_i; the angle step and the output format.
#include <optional>
#include <string>

#include "api/params.hpp"
#include "engine/fresnel/metals.hpp"

namespace lp::api {

struct ConductorSpec {
  std::optional<std::string> metal;  // the preset the values came from, if any
  Rgb64 eta{}, k{};
};

enum class TableFormat { JsonDocument, Csv };
constexpr auto enum_entries(TableFormat) {
  return std::to_array<EnumEntry<TableFormat>>(
      {{TableFormat::JsonDocument, "json"}, {TableFormat::Csv, "csv"}});
}

struct FresnelRequest {
  double eta_i = 1.0;                      // outside / incident medium (default: air)
  double eta_t = 1.0;                      // dielectric tables only
  std::optional<ConductorSpec> conductor;  // set for conductor tables
  double step = 1.0;                       // degrees
  bool csv = false;
};

// Indices (eta_i, eta_t, eta) lie in limits::kFresnelIndex, k in limits::kFresnelExtinction, step in
// limits::kFresnelStepDeg.
// Throws ApiError 400 "invalid_field" naming the parameter: missing, not a finite number, out of range,
// an unknown metal, or a mix of dielectric and conductor parameters. (Unknown and repeated parameters
// are refused for every endpoint by the server's query policy.)
FresnelRequest parse_fresnel_query(const Query& q);

}  // namespace lp::api
