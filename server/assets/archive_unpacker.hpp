#pragma once
// Unpacking an uploaded zip or tar archive (plain or gzip-compressed) with libarchive, refusing what could
// write outside the folder or fill the disk: members named by an absolute path or with a '..' component,
// links (symbolic and hard), devices, FIFOs and sockets, more members than allowed, and more unpacked
// bytes than allowed. The bytes are counted while they are read, never taken from a member's header.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace lp::server {

struct ArchiveLimits {
  int64_t max_bytes = 0;    // unpacked bytes of all members together
  int64_t max_members = 0;  // members of any type, folders included
};

struct UnpackedFile {
  std::string path;  // inside the folder, '/'-separated, without '.' components
  int64_t bytes = 0;
};

// Unpacks `archive` into `dir`, an existing empty folder, writing only regular files (each flushed to
// disk) and folders. Throws api::ApiError: 415 for bytes that are no zip or tar archive, 422 for a
// corrupt or truncated one (or an encrypted member), 400 for a refused member, 413 past a limit. Files
// written before an error stay in `dir`; the caller removes it. I/O failures throw std::runtime_error.
std::vector<UnpackedFile> unpack_archive(std::span<const uint8_t> archive, const std::filesystem::path& dir,
                                         const ArchiveLimits& limits);

}  // namespace lp::server
