#pragma once
// A fingerprint of a map (a hash of its pixels and its size), so a render continued after a restart can tell
// the map it renders is still the one it started with. Computed once per map and cached with it.
#include <string>

#include "engine/envmap/envmap.hpp"

namespace lp::server {

std::string envmap_fingerprint(const EnvMap& map);

}  // namespace lp::server
