#pragma once
// Fresh temporary directories for tests.
#include <filesystem>

namespace lp::test {

// A new, empty directory under /tmp; the caller removes it.
std::filesystem::path make_temp_dir();

// A fresh, empty temporary directory, removed with everything in it at the end.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace lp::test
