#pragma once
// The content hash of a map: a SHA-256 (storage/content_hash.hpp) of its size and its pixels, written as
// 64 hex digits, '-' and WIDTHxHEIGHT. It names a map wherever its content decides reuse or trust: a
// prefiltered chain answers every map of the same hash, a render continues only on the map it started
// with, and a worker fetches and checks a split render's map by it. Computed once per map and cached with
// it.
#include <string>

#include "engine/envmap/envmap.hpp"

namespace lp::server {

std::string envmap_content_hash(const EnvMap& map);

}  // namespace lp::server
