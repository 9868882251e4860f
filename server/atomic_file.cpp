#include "server/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace lp::server {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what, const fs::path& path) {
  throw std::runtime_error("cannot " + what + " " + path.string() + ": " + std::strerror(errno));
}

// A descriptor closed on every path out.
class Fd {
 public:
  Fd(const fs::path& path, int flags, mode_t mode = 0) : fd_(::open(path.c_str(), flags | O_CLOEXEC, mode)) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

void write_all(const Fd& fd, std::span<const uint8_t> bytes, const fs::path& path) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd.get(), bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write", path);
    bytes = bytes.subspan(size_t(n));
  }
}

fs::path temp_path_for(const fs::path& path) {
  static std::atomic<uint64_t> counter{0};
  return path.parent_path() / (path.filename().string() + std::string(kTempFileMarker) +
                               std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
}

}  // namespace

void write_file_atomically(const fs::path& path, std::span<const uint8_t> bytes) {
  const fs::path temp = temp_path_for(path);
  try {
    {
      Fd file(temp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (file.get() < 0) fail("create", temp);
      write_all(file, bytes, temp);
      if (::fsync(file.get()) != 0) fail("flush", temp);
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) fail("rename to", path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
  Fd dir(path.parent_path().empty() ? fs::path(".") : path.parent_path(), O_RDONLY | O_DIRECTORY);
  if (dir.get() < 0 || ::fsync(dir.get()) != 0) fail("flush the directory of", path);
}

void write_file_atomically(const fs::path& path, std::string_view text) {
  write_file_atomically(path, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

}  // namespace lp::server
