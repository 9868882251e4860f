#pragma once
// Inputs of the benchmarks: the full-size (1024x512) CC0 maps and the bunny of ../shared/data when that
// folder is beside the repository, else the reduced copies in tests/data (figures then differ).
#include <filesystem>
#include <string>

namespace lp::bench {

std::filesystem::path envmap_path(const std::string& file);
std::filesystem::path mesh_path(const std::string& file);

}  // namespace lp::bench
