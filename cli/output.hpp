#pragma once
// Where a command writes its result: the file of -o FILE, or standard output (no -o, or -o -). A file is
// written beside its final name and renamed into place once complete, so a command that fails leaves
// no partial file behind.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lp::cli {

// Checks made before any work, so that a long render is not wasted on an output it cannot write.
// Refuses (bad_request) to write binary data to standard output when it is a terminal and no -o was given;
// `-o -` asks for it anyway.
void refuse_binary_to_terminal(const std::optional<std::string>& file);
// Refuses (not_found) a folder that does not exist, for an output file inside it or as the folder itself.
void require_folder(const std::filesystem::path& folder);
void require_folder_of(const std::string& file);

class Output {
 public:
  explicit Output(const std::optional<std::string>& file);
  ~Output();  // an unfinished file is removed
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  bool is_stdout() const { return !file_; }
  // Throws lp::Error(WriteFailed) naming the file.
  void write(std::string_view bytes);
  void write(std::span<const uint8_t> bytes);
  // Flushes, and renames the file into place.
  void finish();

 private:
  [[noreturn]] void fail(const std::string& what) const;

  std::optional<std::filesystem::path> file_;
  std::filesystem::path partial_;
  std::FILE* stream_ = nullptr;
  bool finished_ = false;
};

}  // namespace lp::cli
