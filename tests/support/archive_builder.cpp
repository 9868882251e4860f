#include "support/archive_builder.hpp"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace lp::test {
namespace {

struct WriterCloser {
  void operator()(archive* a) const { archive_write_free(a); }
};
struct EntryCloser {
  void operator()(archive_entry* e) const { archive_entry_free(e); }
};

la_ssize_t append(archive*, void* out, const void* data, size_t n) {
  static_cast<std::string*>(out)->append(static_cast<const char*>(data), n);
  return la_ssize_t(n);
}

void check(archive* a, int r, const char* what) {
  if (r < ARCHIVE_WARN)
    throw std::runtime_error(std::string(what) + ": " +
                             (archive_error_string(a) ? archive_error_string(a) : "?"));
}

void set_format(archive* a, ArchiveFormat format) {
  if (format == ArchiveFormat::Zip) {
    check(a, archive_write_set_format_zip(a), "zip");
    check(a, archive_write_zip_set_compression_deflate(a), "deflate");
    return;
  }
  check(a, archive_write_set_format_pax_restricted(a), "tar");
  if (format == ArchiveFormat::TarGz) check(a, archive_write_add_filter_gzip(a), "gzip");
}

void describe(archive_entry* e, const ArchiveMember& m) {
  archive_entry_set_pathname(e, m.path.c_str());
  archive_entry_set_perm(e, 0644);
  archive_entry_set_mtime(e, 1700000000, 0);
  switch (m.type) {
    case MemberType::File:
      archive_entry_set_filetype(e, AE_IFREG);
      archive_entry_set_size(e, m.zero_bytes ? m.zero_bytes : int64_t(m.content.size()));
      break;
    case MemberType::Folder:
      archive_entry_set_filetype(e, AE_IFDIR);
      archive_entry_set_perm(e, 0755);
      break;
    case MemberType::Symlink:
      archive_entry_set_filetype(e, AE_IFLNK);
      archive_entry_set_symlink(e, m.target.c_str());
      break;
    case MemberType::Hardlink:
      archive_entry_set_filetype(e, AE_IFREG);
      archive_entry_set_hardlink(e, m.target.c_str());
      break;
    case MemberType::CharDevice:
      archive_entry_set_filetype(e, AE_IFCHR);
      archive_entry_set_rdev(e, 0x0103);  // /dev/null's numbers
      break;
    case MemberType::Fifo:
      archive_entry_set_filetype(e, AE_IFIFO);
      break;
  }
}

void write_data(archive* a, const ArchiveMember& m) {
  if (m.type != MemberType::File) return;
  if (!m.zero_bytes) {
    if (archive_write_data(a, m.content.data(), m.content.size()) < 0) check(a, ARCHIVE_FATAL, "data");
    return;
  }
  const std::string zeros(64 * 1024, '\0');
  for (int64_t left = m.zero_bytes; left > 0; left -= int64_t(zeros.size()))
    if (archive_write_data(a, zeros.data(), size_t(std::min<int64_t>(left, int64_t(zeros.size())))) < 0)
      check(a, ARCHIVE_FATAL, "data");
}

}  // namespace

std::string make_archive(ArchiveFormat format, const std::vector<ArchiveMember>& members) {
  std::string out;
  std::unique_ptr<archive, WriterCloser> a(archive_write_new());
  set_format(a.get(), format);
  check(a.get(), archive_write_set_bytes_in_last_block(a.get(), 1), "block");
  check(a.get(), archive_write_open(a.get(), &out, nullptr, append, nullptr), "open");
  for (const ArchiveMember& m : members) {
    std::unique_ptr<archive_entry, EntryCloser> e(archive_entry_new());
    describe(e.get(), m);
    check(a.get(), archive_write_header(a.get(), e.get()), "header");
    write_data(a.get(), m);
  }
  check(a.get(), archive_write_close(a.get()), "close");
  return out;
}

ArchiveMember file_member(std::string path, std::string content) {
  return {std::move(path), std::move(content)};
}

ArchiveMember folder_member(std::string path) {
  return {std::move(path), "", MemberType::Folder};
}

std::string glb_bytes(const std::string& json) {
  std::string chunk = json;
  chunk.resize((chunk.size() + 3) / 4 * 4, ' ');
  auto u32 = [](uint32_t v) {
    return std::string{char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff), char(v >> 24 & 0xff)};
  };
  return "glTF" + u32(2) + u32(uint32_t(12 + 8 + chunk.size())) + u32(uint32_t(chunk.size())) + "JSON" +
         chunk;
}

}  // namespace lp::test
