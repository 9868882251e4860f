#pragma once
// Zip and tar archives built in memory with libarchive, for tests of asset uploads: any member names
// (absolute, with '..'), links, devices, and large members of zeros (compressing to almost nothing).
#include <cstdint>
#include <string>
#include <vector>

namespace lp::test {

enum class ArchiveFormat { Zip, Tar, TarGz };

enum class MemberType { File, Folder, Symlink, Hardlink, CharDevice, Fifo };

struct ArchiveMember {
  std::string path;
  std::string content;  // a file's bytes
  MemberType type = MemberType::File;
  std::string target{};    // a link's target
  int64_t zero_bytes = 0;  // a file of this many zero bytes instead of `content`
};

std::string make_archive(ArchiveFormat format, const std::vector<ArchiveMember>& members);

// A member of each kind, for brevity.
ArchiveMember file_member(std::string path, std::string content);
ArchiveMember folder_member(std::string path);

// The first bytes of a binary glTF file (magic, version 2, length) followed by `json` as its JSON chunk.
std::string glb_bytes(const std::string& json);

}  // namespace lp::test
