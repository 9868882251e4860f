#pragma once
// A small filesystem of its own that a test can fill: a tmpfs mounted at a fresh directory inside a user
// and mount namespace (unshare(1), no root needed), held by a sleeping process. Servers started through
// launcher() (nsenter(1) into that namespace) keep their state on it across restarts, and the test reaches
// the same files through /proc/PID/root.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lp::test {

class SmallDisk {
 public:
  explicit SmallDisk(int64_t bytes);
  ~SmallDisk();
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;

  // The mount point, as a server started through launcher() sees it.
  const std::filesystem::path& path() const { return path_; }
  // The same directory as this process sees it.
  std::filesystem::path outside() const;
  // The command a server is started under to see the filesystem.
  std::vector<std::string> launcher() const;

  // Writes a file until the filesystem is full, then gives `room` bytes back; free() removes it.
  void fill(int64_t room = 0) const;
  void free() const;

 private:
  std::filesystem::path path_;
  int holder_ = -1;
};

}  // namespace lp::test
