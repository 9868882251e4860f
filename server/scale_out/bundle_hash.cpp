#include "server/scale_out/bundle_hash.hpp"

#include <algorithm>

#include "server/storage/content_hash.hpp"

namespace lp::server {
namespace {

constexpr std::string_view kSuffix = "-bundle";

}  // namespace

std::string bundle_hash(const std::filesystem::path& folder, std::vector<std::string> files) {
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files_content_hash(folder, files) + std::string(kSuffix);
}

bool is_bundle_hash(std::string_view text) {
  return text.ends_with(kSuffix) && is_content_hash(text.substr(0, text.size() - kSuffix.size()));
}

}  // namespace lp::server
