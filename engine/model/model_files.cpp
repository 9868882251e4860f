#include "engine/model/model_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <system_error>
#include <utility>

#include "engine/core/error.hpp"

namespace lp {
namespace fs = std::filesystem;

ModelFiles::ModelFiles(fs::path folder, int64_t max_bytes, ModelReserve reserve)
    : max_bytes_(max_bytes), reserve_(std::move(reserve)) {
  if (!folder.empty()) {
    std::error_code ec;
    folder_ = fs::canonical(folder, ec);
    if (ec) throw Error(ErrorKind::NotFound, "model folder not found: " + folder.filename().string());
  }
}

void ModelFiles::count(int64_t bytes, const std::string& what) {
  bytes_ += bytes;
  if (bytes_ > max_bytes_)
    throw Error(ErrorKind::TooLarge,
                fmt::format("model files are over {} bytes together (at {})", max_bytes_, what));
}

FileStamp FileStamp::of(const fs::path& path) {
  std::error_code size_error, time_error;
  const auto size = fs::file_size(path, size_error);
  const auto modified = fs::last_write_time(path, time_error);
  if (size_error || time_error) return {path};
  return {path, size, modified};
}

FileStamp ModelFiles::resolve(const std::string& relative) {
  if (folder_.empty())
    throw Error(ErrorKind::InvalidArgument,
                "a model read from memory cannot refer to the file '" + relative.substr(0, 128) + "'");
  const fs::path rel = fs::path(relative).lexically_normal();
  if (relative.empty() || rel.is_absolute() || rel.has_root_name() || rel.has_root_directory() ||
      (!rel.empty() && *rel.begin() == ".."))
    throw Error(ErrorKind::InvalidArgument,
                "model refers to '" + relative.substr(0, 128) + "', which is not a path inside its folder");
  std::error_code ec;
  const fs::path full = fs::weakly_canonical(folder_ / rel, ec);
  const auto [end, _] = std::mismatch(folder_.begin(), folder_.end(), full.begin(), full.end());
  if (ec || end != folder_.end())
    throw Error(ErrorKind::InvalidArgument,
                "model refers to '" + relative.substr(0, 128) + "', which leads outside its folder");
  const auto seen =
      std::find_if(stamps_.begin(), stamps_.end(), [&](const FileStamp& s) { return s.path == full; });
  return seen != stamps_.end() ? *seen : stamps_.emplace_back(FileStamp::of(full));
}

std::vector<uint8_t> ModelFiles::read(const std::string& relative, const std::string& what) {
  const fs::path path = resolve(relative).path;
  auto bytes = read_file(path, max_bytes_ - bytes_, reserve_);
  count(int64_t(bytes.size()), what);
  return bytes;
}

std::vector<uint8_t> ModelFiles::read_model(const fs::path& path, const std::string& what) {
  auto bytes = read_file(path, max_bytes_ - bytes_, reserve_);
  count(int64_t(bytes.size()), what);
  return bytes;
}

std::string ModelFiles::cache_key(const std::string& relative) {
  const FileStamp stamp = resolve(relative);
  return fmt::format("{}|{}|{}", stamp.path.string(), stamp.size, stamp.modified.time_since_epoch().count());
}

std::vector<uint8_t> ModelFiles::read_file(const fs::path& path, int64_t max_bytes,
                                           const ModelReserve& reserve) {
  const std::string name = path.filename().string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(ErrorKind::NotFound, "file not found: " + name);
  const auto size = fs::file_size(path, ec);
  if (ec) throw Error(ErrorKind::NotFound, "file not readable: " + name);
  if (int64_t(size) > max_bytes)
    throw Error(ErrorKind::TooLarge, fmt::format("{} is over the {} bytes left for the model's files", name,
                                                 std::max<int64_t>(max_bytes, 0)));
  if (reserve) reserve(file_load_bytes(int64_t(size)), "the file " + name);
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(size);
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
    throw Error(ErrorKind::NotFound, "file not readable: " + name);
  return bytes;
}

std::string decode_uri(const std::string& uri) {
  std::string out;
  const auto hex = [](char c) {
    return c >= '0' && c <= '9'
               ? c - '0'
               : (c >= 'a' && c <= 'f' ? c - 'a' + 10 : (c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1));
  };
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace lp
