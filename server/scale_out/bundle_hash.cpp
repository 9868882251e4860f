#include "server/scale_out/bundle_hash.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <stdexcept>

namespace lp::server {
namespace {

constexpr size_t kBlockBytes = size_t(1) << 20;
constexpr std::string_view kSuffix = "-bundle";
constexpr size_t kHexDigits = 16;

uint64_t hash_of(std::string_view bytes) {
  return std::hash<std::string_view>{}(bytes);
}

// "SIZE:HASH" of a file's bytes, hashed a block at a time (no buffer as large as the file), then the
// blocks' hashes together.
std::string file_digest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.filename().string());
  std::string block(kBlockBytes, '\0');
  std::string block_hashes;
  int64_t size = 0;
  while (in) {
    in.read(block.data(), std::streamsize(block.size()));
    const auto n = size_t(in.gcount());
    if (n == 0) break;
    size += int64_t(n);
    const uint64_t h = hash_of(std::string_view(block.data(), n));
    block_hashes.append(reinterpret_cast<const char*>(&h), sizeof h);
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path.filename().string());
  return fmt::format("{}:{:016x}", size, hash_of(block_hashes));
}

}  // namespace

std::string bundle_hash(const std::filesystem::path& folder, std::vector<std::string> files) {
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  std::string manifest;
  for (const auto& file : files) {
    manifest += file;
    manifest += '\0';
    manifest += file_digest(folder / file);
    manifest += '\n';
  }
  return fmt::format("{:016x}{}", hash_of(manifest), kSuffix);
}

bool is_bundle_hash(std::string_view text) {
  if (text.size() != kHexDigits + kSuffix.size() || !text.ends_with(kSuffix)) return false;
  return std::all_of(text.begin(), text.begin() + kHexDigits,
                     [](char c) { return std::isdigit(uint8_t(c)) || (c >= 'a' && c <= 'f'); });
}

}  // namespace lp::server
