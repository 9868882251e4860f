#pragma once
// Files that are either whole or absent: the bytes go to a temporary file in the same directory, which
// is flushed to disk, renamed over the target, and the directory flushed, so a crash at any point leaves
// the old file or the new one, never a part.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace lp::server {

// Throws std::runtime_error naming the path and the system error.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

// Temporary files of writes that a crash cut short carry this marker in their name.
inline constexpr std::string_view kTempFileMarker = ".tmp-";

}  // namespace lp::server
