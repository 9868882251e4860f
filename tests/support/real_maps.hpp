#pragma once
// The real maps of tests/data/envmaps, loaded once per test binary.
#include <memory>
#include <string>

#include "engine/envmap/envmap.hpp"

namespace lp::test {

std::shared_ptr<const EnvMap> real_map(const std::string& file);  // cached by file name

}  // namespace lp::test
