#include "server/scale_out/bundle_archive.hpp"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine/core/error.hpp"
#include "engine/model/model_files.hpp"

namespace lp::server {
namespace {

constexpr int64_t kMemberOverheadBytes = 4096;  // ustar header, a pax header of a 1 KiB path, padding
constexpr int64_t kEndBytes = 12 * 1024;        // two zero blocks, padded to a 10 KiB record

struct WriterCloser {
  void operator()(archive* a) const { archive_write_free(a); }
};
struct EntryCloser {
  void operator()(archive_entry* e) const { archive_entry_free(e); }
};

la_ssize_t append(archive*, void* out, const void* data, size_t n) {
  auto& bytes = *static_cast<std::vector<uint8_t>*>(out);
  bytes.insert(bytes.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + n);
  return la_ssize_t(n);
}

void check(archive* a, int r, const char* what) {
  if (r < ARCHIVE_WARN)
    throw std::runtime_error(std::string("cannot write a mesh bundle (") + what +
                             "): " + (archive_error_string(a) ? archive_error_string(a) : "unknown error"));
}

void write_member(archive* a, const std::string& name, const std::vector<uint8_t>& bytes) {
  const std::unique_ptr<archive_entry, EntryCloser> entry(archive_entry_new());
  archive_entry_set_pathname(entry.get(), name.c_str());
  archive_entry_set_filetype(entry.get(), AE_IFREG);
  archive_entry_set_perm(entry.get(), 0644);
  archive_entry_set_size(entry.get(), int64_t(bytes.size()));
  check(a, archive_write_header(a, entry.get()), "header");
  if (!bytes.empty() && archive_write_data(a, bytes.data(), bytes.size()) < 0)
    check(a, ARCHIVE_FATAL, "data");
}

}  // namespace

int64_t bundle_tar_bytes(int64_t file_bytes, int64_t files) {
  return file_bytes + files * kMemberOverheadBytes + kEndBytes;
}

BundleSize bundle_size(const MeshBundle& bundle) {
  BundleSize size;
  for (const auto& file : bundle.files) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(bundle.folder / file, ec);
    if (ec) throw Error(ErrorKind::NotFound, "a file of the mesh bundle is gone: " + file);
    size.file_bytes += int64_t(bytes);
    size.largest_file_bytes = std::max(size.largest_file_bytes, int64_t(bytes));
  }
  size.tar_bytes = bundle_tar_bytes(size.file_bytes, int64_t(bundle.files.size()));
  return size;
}

std::vector<uint8_t> write_bundle_tar(const MeshBundle& bundle, const BundleSize& size) {
  std::vector<uint8_t> out;
  out.reserve(size_t(size.tar_bytes));
  const std::unique_ptr<archive, WriterCloser> a(archive_write_new());
  if (!a) throw std::bad_alloc();
  check(a.get(), archive_write_set_format_pax_restricted(a.get()), "format");
  check(a.get(), archive_write_set_bytes_in_last_block(a.get(), 1), "block size");
  check(a.get(), archive_write_open(a.get(), &out, nullptr, append, nullptr), "open");
  for (const auto& file : bundle.files)
    write_member(a.get(), file, ModelFiles::read_file(bundle.folder / file, size.largest_file_bytes));
  check(a.get(), archive_write_close(a.get()), "close");
  return out;
}

}  // namespace lp::server
