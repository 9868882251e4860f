#include "engine/fresnel/metals.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace lp {
namespace {

// Optical constants n, k of the luxpop.com database of measured values, as distributed with Mitsuba 0.6
// (data/ior/{Au,Ag,Cu,Al}.{eta,k}.spd; pbrt-v3's copper table is the same data), read at the
// tabulated wavelengths nearest 650, 550 and 450 nm: 652.548 nm (1.90 eV), 551.041 nm (2.25 eV) and
// 450.852 nm (2.75 eV), so no value is interpolated.
constexpr std::array<ConductorPreset, 4> kMetals = {{
    {"gold", {0.166000, 0.345500, 1.502125}, {3.150000, 2.730625, 1.875875}},
    {"silver", {0.140000, 0.124375, 0.151063}, {4.150000, 3.348125, 2.478750}},
    {"copper", {0.214000, 0.950375, 1.165312}, {3.670000, 2.576500, 2.397625}},
    {"aluminium", {1.490000, 0.963000, 0.620313}, {7.820000, 6.700000, 5.480000}},
}};

}  // namespace

const std::vector<std::string>& metal_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& m : kMetals) v.emplace_back(m.name);
    return v;
  }();
  return names;
}

const ConductorPreset& lookup_metal(std::string_view name) {
  const auto it = std::find_if(kMetals.begin(), kMetals.end(), [&](const auto& m) { return m.name == name; });
  if (it != kMetals.end()) return *it;
  std::string known;
  for (const auto& n : metal_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error(ErrorKind::InvalidArgument, "unknown metal '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace lp
