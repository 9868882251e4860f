#pragma once
// The state directory (--state-dir): what the server keeps across restarts. Layout:
//   maps/NAME.json      a map's record; maps/NAME.FORMAT its file as uploaded (none for maps loaded by path)
//   renders/ID.json     a render's record; renders/ID.SPP.exr its image after SPP samples per pixel
//   assets/NAME.json    a model asset's record; asset-files/NAME/ its files (assets/stored_assets.hpp)
// Records and the files they name live apart or under distinct suffixes, so no two names collide. Every
// file is written atomically (atomic_file.hpp); the records are the truth: at start a file that no record
// names is left over from a crash and removed, and a record whose file is missing is dropped. One server
// at a time: the directory is locked while open.
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace lp::server {

class StateStore {
 public:
  // Creates the directory and its folders if needed, locks it, and removes temporary files of writes a
  // crash cut short. Throws std::runtime_error with a message for the operator.
  explicit StateStore(std::filesystem::path dir);
  ~StateStore();
  StateStore(const StateStore&) = delete;
  StateStore& operator=(const StateStore&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path maps_dir() const { return dir_ / "maps"; }
  std::filesystem::path renders_dir() const { return dir_ / "renders"; }
  std::filesystem::path assets_dir() const { return dir_ / "assets"; }
  std::filesystem::path asset_files_dir() const { return dir_ / "asset-files"; }

  // The *.json records of a folder that parse as JSON objects, by file name; the others are skipped
  // with a warning.
  std::vector<std::pair<std::filesystem::path, nlohmann::json>> read_records(
      const std::filesystem::path& folder) const;
  void write_record(const std::filesystem::path& path, const nlohmann::json& record) const;
  void write_bytes(const std::filesystem::path& path, std::span<const uint8_t> bytes) const;
  // Removes a file if it exists; a failure is logged, not thrown.
  void remove(const std::filesystem::path& path) const;
  // Removes a file or folder that no record names, saying so in the log.
  void remove_leftover(const std::filesystem::path& path) const;

  // Held while a map's files and its registry entry change together.
  std::mutex& maps_mutex() { return maps_mutex_; }
  // The same for an asset's folder, record and registry entry.
  std::mutex& assets_mutex() { return assets_mutex_; }

 private:
  std::filesystem::path dir_;
  int lock_fd_ = -1;
  std::mutex maps_mutex_;
  std::mutex assets_mutex_;
};

}  // namespace lp::server
