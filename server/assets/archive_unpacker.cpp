#include "server/assets/archive_unpacker.hpp"

#include <archive.h>
#include <archive_entry.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <optional>

#include "api/api_error.hpp"
#include "server/assets/asset_limits.hpp"
#include "server/storage/atomic_file.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;
using api::ApiError;
using api::ErrorCode;

constexpr size_t kMaxPathBytes = 1024;
constexpr size_t kMaxNameBytes = 255;  // one path component, as Linux file systems allow
constexpr size_t kReadBlockBytes = 64 * 1024;
constexpr const char* kNotAnArchive =
    "the body is neither a .glb or .gltf model nor a zip or tar (optionally gzip) archive";

struct ArchiveCloser {
  void operator()(archive* a) const { archive_read_free(a); }
};
using Reader = std::unique_ptr<archive, ArchiveCloser>;

Reader open_reader(std::span<const uint8_t> bytes) {
  Reader a(archive_read_new());
  if (!a) throw std::bad_alloc();
  archive_read_support_filter_none(a.get());
  archive_read_support_filter_gzip(a.get());
  archive_read_support_format_zip(a.get());
  archive_read_support_format_tar(a.get());
  if (archive_read_open_memory(a.get(), bytes.data(), bytes.size()) != ARCHIVE_OK)
    throw ApiError(ErrorCode::UnsupportedMediaType, kNotAnArchive);
  return a;
}

ApiError too_many_members(const ArchiveLimits& limits) {
  return ApiError(ErrorCode::TooLarge, fmt::format("the archive holds more than {} members (--{})",
                                                   limits.max_members, kMaxAssetFiles.flag));
}

bool is_gzip(std::span<const uint8_t> bytes) {
  return bytes.size() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b;
}

// libarchive reads a zip's whole central directory into memory (a few hundred bytes an entry) before
// it returns the first member, so the member limit is checked before it opens the bytes: every entry
// it can read there starts with the signature "PK\1\2", and their count over all the bytes bounds the
// members (member data holding the signature could only make a refusal early, never an acceptance
// wrong). Compressed bytes are read as a stream, one member at a time, and counted as they come.
void check_directory_entries(std::span<const uint8_t> bytes, const ArchiveLimits& limits) {
  if (is_gzip(bytes)) return;
  static constexpr std::array<uint8_t, 4> kEntry = {'P', 'K', 1, 2};
  const std::boyer_moore_horspool_searcher searcher(kEntry.begin(), kEntry.end());
  int64_t entries = 0;
  for (auto at = bytes.begin(); (at = std::search(at, bytes.end(), searcher)) != bytes.end(); ++at)
    if (++entries > limits.max_members) throw too_many_members(limits);
}

std::string reader_error(archive* a) {
  const char* message = archive_error_string(a);
  return message ? api::excerpt(message) : "unknown error";
}

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
  throw ApiError(ErrorCode::InvalidArgument, "archive member '" + api::excerpt(name) + "' " + why);
}

// The member's path inside the folder, '.' components dropped; empty for the folder itself.
std::string safe_relative_path(const char* raw) {
  if (!raw || !*raw) refuse("", "has no name");
  const std::string name = raw;
  if (name.size() > kMaxPathBytes) refuse(name, fmt::format("has a path over {} bytes", kMaxPathBytes));
  if (name.front() == '/') refuse(name, "has an absolute path");
  std::string out;
  size_t start = 0;
  while (start <= name.size()) {
    const size_t end = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, end - start);
    start = end + 1;
    if (part.empty() || part == ".") continue;
    if (part == "..") refuse(name, "has a '..' component");
    if (part.size() > kMaxNameBytes) refuse(name, fmt::format("has a name over {} bytes", kMaxNameBytes));
    out += (out.empty() ? "" : "/") + part;
  }
  return out;
}

// Links, devices, FIFOs and sockets are refused: only files and folders are unpacked.
void check_member_type(archive_entry* entry, const std::string& name) {
  if (archive_entry_hardlink(entry)) refuse(name, "is a hard link; only files and folders are accepted");
  if (archive_entry_symlink(entry) || archive_entry_filetype(entry) == AE_IFLNK)
    refuse(name, "is a symbolic link; only files and folders are accepted");
  const auto type = archive_entry_filetype(entry);
  if (type != AE_IFREG && type != AE_IFDIR)
    refuse(name, "is a device, FIFO or socket; only files and folders are accepted");
}

class Unpacker {
 public:
  Unpacker(archive* a, const fs::path& dir, const ArchiveLimits& limits)
      : a_(a), dir_(dir), limits_(limits) {}

  std::vector<UnpackedFile> run() {
    archive_entry* entry = nullptr;
    for (;;) {
      const int r = archive_read_next_header(a_, &entry);
      if (r == ARCHIVE_EOF) break;
      if (r != ARCHIVE_OK && r != ARCHIVE_WARN) header_failed();
      if (++members_ > limits_.max_members) throw too_many_members(limits_);
      unpack(entry);
    }
    return std::move(files_);
  }

 private:
  [[noreturn]] void header_failed() const {
    if (members_ == 0 && archive_format(a_) == 0)
      throw ApiError(ErrorCode::UnsupportedMediaType, kNotAnArchive);
    throw ApiError(ErrorCode::Corrupt, "the archive is corrupt or truncated: " + reader_error(a_));
  }

  void unpack(archive_entry* entry) {
    const char* raw = archive_entry_pathname(entry);
    const std::string path = safe_relative_path(raw);
    check_member_type(entry, raw);
    if (archive_entry_filetype(entry) == AE_IFDIR)
      make_folder(dir_ / path, raw);
    else if (path.empty())
      refuse(raw, "names the archive's root as a file");
    else
      write_file(path, raw);
  }

  void make_folder(const fs::path& folder, const std::string& name) const {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(fs::symlink_status(folder)))
      refuse(name, "conflicts with a file of the same name in the archive");
  }

  void write_file(const std::string& path, const std::string& name) {
    const fs::path target = dir_ / path;
    make_folder(target.parent_path(), name);
    std::error_code ec;
    if (fs::symlink_status(target, ec).type() != fs::file_type::not_found)
      refuse(name, "appears twice in the archive");
    NewFile file(target);
    int64_t bytes = 0;
    std::array<uint8_t, kReadBlockBytes> block;
    for (;;) {
      const la_ssize_t n = archive_read_data(a_, block.data(), block.size());
      if (n == 0) break;
      if (n < 0)
        throw ApiError(ErrorCode::Corrupt,
                       "archive member '" + api::excerpt(name) + "' cannot be read: " + reader_error(a_));
      total_ += n;
      if (total_ > limits_.max_bytes)
        throw ApiError(ErrorCode::TooLarge, fmt::format("the archive unpacks to more than {} bytes (--{})",
                                                        limits_.max_bytes, kMaxAssetMb.flag));
      file.write({block.data(), size_t(n)});
      bytes += n;
    }
    file.finish();
    files_.push_back({path, bytes});
  }

  archive* a_;
  const fs::path& dir_;
  const ArchiveLimits& limits_;
  int64_t members_ = 0;
  int64_t total_ = 0;
  std::vector<UnpackedFile> files_;
};

}  // namespace

std::vector<UnpackedFile> unpack_archive(std::span<const uint8_t> archive, const fs::path& dir,
                                         const ArchiveLimits& limits) {
  check_directory_entries(archive, limits);
  const Reader reader = open_reader(archive);
  return Unpacker(reader.get(), dir, limits).run();
}

}  // namespace lp::server
