#pragma once
// Files that are either whole or absent: the bytes go to a temporary file in the same directory, which
// is flushed to disk, renamed over the target, and the directory flushed, so a crash at any point leaves
// the old file or the new one, never a part.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace lp::server {

// Throw StorageError (storage_error.hpp) naming the system error.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

// Temporary files and folders start with this prefix, which no resource name (resource_name.hpp) and no
// render id can start with, so that the start-up sweep of writes a crash cut short matches only them.
inline constexpr std::string_view kTempFilePrefix = ".tmp-";

// A fresh name beside `path`, starting with kTempFilePrefix, for a file or folder written before it is
// renamed to `path`.
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

// Flushes a folder's entries (files created, renamed or removed in it) to disk. Throws like the writes.
void sync_directory(const std::filesystem::path& dir);

// A file that must not exist yet (nor be a link), written in pieces and flushed to disk by finish().
// Every member throws StorageError.
class NewFile {
 public:
  explicit NewFile(std::filesystem::path path);
  ~NewFile();
  NewFile(const NewFile&) = delete;
  NewFile& operator=(const NewFile&) = delete;

  void write(std::span<const uint8_t> bytes);
  void finish();  // flushes and closes

 private:
  std::filesystem::path path_;
  int fd_;
};

}  // namespace lp::server
