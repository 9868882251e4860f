// The asset archive unpacker (libarchive: zip, tar, gzip) and the model-file check on any bytes, into a
// fresh folder. Every refusal must be a 4xx ApiError with a short message; whatever is accepted must lie
// inside the folder as plain files and folders (no links), within the byte limit, as the result lists it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "fuzz_input.hpp"
#include "server/assets/archive_unpacker.hpp"
#include "server/assets/asset_folder.hpp"

namespace {

namespace fs = std::filesystem;

constexpr lp::server::ArchiveLimits kLimits{1 << 20, 64};

[[noreturn]] void fail(const char* what, const fs::path& path) {
  std::fprintf(stderr, "%s: %s\n", what, path.c_str());
  std::abort();
}

// A folder of this process in memory when the machine has one (files are flushed one by one).
fs::path scratch_root() {
  const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  const fs::path root = base / ("archive-unpacker-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(root);
  return root;
}

void check_written(const fs::path& dir, const std::vector<lp::server::UnpackedFile>& files) {
  int64_t total = 0;
  for (const auto& f : files) {
    const fs::path path = dir / f.path;
    if (!fs::is_regular_file(fs::symlink_status(path)) || int64_t(fs::file_size(path)) != f.bytes)
      fail("a listed file is not as listed", path);
    total += f.bytes;
  }
  if (total > kLimits.max_bytes) fail("more bytes than the limit", dir);
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (!entry.is_regular_file() && !entry.is_directory()) fail("neither a file nor a folder", entry.path());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fs::path root = scratch_root();
  const fs::path dir = root / "unpacked";
  fs::remove_all(dir);
  fs::create_directory(dir);
  try {
    const auto files = lp::server::unpack_archive({data, size}, dir, kLimits);
    check_written(dir, files);
    lp::server::find_model_file(files);
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
  }
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.path() != dir) fail("written outside the folder", entry.path());
  fs::remove_all(dir);
  return 0;
}
