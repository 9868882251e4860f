#include "server/storage/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <utility>

#include "server/storage/storage_error.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what, const fs::path& path) {
  throw StorageError(what, path, errno);
}

}  // namespace

NewFile::NewFile(fs::path path)
    : path_(std::move(path)),
      fd_(::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644)) {
  if (fd_ < 0) fail("create", path_);
}

NewFile::~NewFile() {
  if (fd_ >= 0) ::close(fd_);
}

void NewFile::write(std::span<const uint8_t> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write", path_);
    bytes = bytes.subspan(size_t(n));
  }
}

void NewFile::finish() {
  if (::fsync(fd_) != 0) fail("flush", path_);
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) fail("close", path_);
}

fs::path temporary_path_for(const fs::path& path) {
  static std::atomic<uint64_t> counter{0};
  return path.parent_path() / (std::string(kTempFilePrefix) + path.filename().string() + "-" +
                               std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
}

void sync_directory(const fs::path& dir) {
  const int fd = ::open((dir.empty() ? fs::path(".") : dir).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail("open the directory", dir);
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  if (!synced) fail("flush the directory", dir);
}

void write_file_atomically(const fs::path& path, std::span<const uint8_t> bytes) {
  const fs::path temp = temporary_path_for(path);
  try {
    NewFile file(temp);
    file.write(bytes);
    file.finish();
    if (::rename(temp.c_str(), path.c_str()) != 0) fail("rename", path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
  sync_directory(path.parent_path());
}

void write_file_atomically(const fs::path& path, std::string_view text) {
  write_file_atomically(path, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

}  // namespace lp::server
