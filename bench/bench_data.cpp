#include "bench_data.hpp"

#include "support/test_data.hpp"

namespace lp::bench {
namespace {

std::filesystem::path prefer_full_size(const std::string& folder, const std::string& file,
                                       const std::filesystem::path& fallback) {
  const auto full = std::filesystem::path(LIGHTPROBE_SHARED_DATA) / folder / file;
  return std::filesystem::exists(full) ? full : fallback;
}

}  // namespace

std::filesystem::path envmap_path(const std::string& file) {
  return prefer_full_size("envmaps", file, test::envmap_path(file));
}

std::filesystem::path mesh_path(const std::string& file) {
  return prefer_full_size("meshes", file, test::mesh_path(file));
}

}  // namespace lp::bench
