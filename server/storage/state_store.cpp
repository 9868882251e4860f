#include "server/storage/state_store.hpp"

#include <fcntl.h>
#include <spdlog/spdlog.h>
#include <sys/file.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "api/params.hpp"
#include "server/storage/atomic_file.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

int lock_directory(const fs::path& dir) {
  const fs::path lock_path = dir / "lock";
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("the state directory " + dir.string() + " is not writable");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    throw std::runtime_error("the state directory " + dir.string() +
                             " is in use by another lightprobe-server");
  }
  return fd;
}

// Files and folders (an asset's, staged) of writes a crash cut short: only the names the server writes.
void remove_temp_files(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.path().filename().string().starts_with(kTempFilePrefix)) {
      spdlog::warn("state: removing {} (a write cut short)", entry.path().string());
      fs::remove_all(entry.path(), ec);
    }
}

}  // namespace

StateStore::StateStore(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  for (const auto& folder : {dir_, maps_dir(), renders_dir(), assets_dir(), asset_files_dir()}) {
    fs::create_directories(folder, ec);
    if (!fs::is_directory(folder))
      throw std::runtime_error("cannot create the state directory " + folder.string() +
                               (ec ? ": " + ec.message() : ""));
  }
  lock_fd_ = lock_directory(dir_);
  remove_temp_files(maps_dir());
  remove_temp_files(renders_dir());
  remove_temp_files(assets_dir());
  remove_temp_files(asset_files_dir());
}

StateStore::~StateStore() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

std::vector<std::pair<fs::path, nlohmann::json>> StateStore::read_records(const fs::path& folder) const {
  std::vector<std::pair<fs::path, nlohmann::json>> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.path().extension() != ".json") continue;
    try {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      auto record = api::parse_json(text, "the record");
      if (in.bad() || !record.is_object()) throw std::runtime_error("not a JSON object");
      out.emplace_back(entry.path(), std::move(record));
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping {}: {}", entry.path().string(), e.what());
    }
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

void StateStore::write_record(const fs::path& path, const nlohmann::json& record) const {
  write_file_atomically(path, record.dump(1) + "\n");
}

void StateStore::write_bytes(const fs::path& path, std::span<const uint8_t> bytes) const {
  write_file_atomically(path, bytes);
}

void StateStore::remove_leftover(const fs::path& path) const {
  spdlog::warn("state: removing {} (no record names it)", fs::relative(path, dir_).string());
  std::error_code ec;
  fs::remove_all(path, ec);
  if (ec) spdlog::warn("state: cannot remove {}: {}", path.string(), ec.message());
}

void StateStore::remove(const fs::path& path) const {
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) spdlog::warn("state: cannot remove {}: {}", path.string(), ec.message());
}

}  // namespace lp::server
