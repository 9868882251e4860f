#include "support/small_disk.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "support/child_process.hpp"
#include "support/temp_dir.hpp"

namespace lp::test {
namespace {

namespace fs = std::filesystem;

bool mounted(int pid, const fs::path& dir) {
  std::ifstream in(fs::path("/proc") / std::to_string(pid) / "mountinfo");
  const std::string field = fmt::format(" {} ", dir.string());
  for (std::string line; std::getline(in, line);)
    if (line.find(field) != std::string::npos) return true;
  return false;
}

}  // namespace

SmallDisk::SmallDisk(int64_t bytes) : path_(make_temp_dir()) {
  const std::string script = "mount -t tmpfs -o size=" + std::to_string(bytes) + " tmpfs " + path_.string() +
                             " && exec sleep 100000";
  holder_ = start_process(
      {"/usr/bin/unshare", "--user", "--map-root-user", "--mount", "/bin/sh", "-c", script}, 2, 2);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!mounted(holder_, path_)) {
    if (waitpid(holder_, nullptr, WNOHANG) == holder_ || std::chrono::steady_clock::now() > deadline) {
      holder_ = -1;
      throw std::runtime_error("cannot mount a tmpfs in a user namespace (unshare --user --mount)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

SmallDisk::~SmallDisk() {
  if (holder_ > 0) {
    kill(holder_, SIGKILL);
    waitpid(holder_, nullptr, 0);
  }
  std::error_code ec;
  fs::remove_all(path_, ec);
}

fs::path SmallDisk::outside() const {
  return fs::path("/proc/" + std::to_string(holder_) + "/root") / path_.relative_path();
}

std::vector<std::string> SmallDisk::launcher() const {
  return {"/usr/bin/nsenter", "--target", std::to_string(holder_), "--user", "--mount", "--"};
}

void SmallDisk::fill(int64_t room) const {
  const fs::path filler = outside() / "filler";
  {
    std::ofstream out(filler, std::ios::binary | std::ios::app);
    const std::string block(4096, 'x');
    while (out.write(block.data(), std::streamsize(block.size())) && out.flush()) {
    }
  }
  const auto size = int64_t(fs::file_size(filler));
  fs::resize_file(filler, uintmax_t(std::max<int64_t>(0, size - room)));
}

void SmallDisk::free() const {
  fs::remove(outside() / "filler");
}

}  // namespace lp::test
