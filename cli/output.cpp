#include "cli/output.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "api/api_error.hpp"
#include "engine/core/error.hpp"

namespace lp::cli {

void refuse_binary_to_terminal(const std::optional<std::string>& file) {
  if (!file && isatty(STDOUT_FILENO))
    throw api::ApiError(api::ErrorCode::BadRequest,
                        "standard output is a terminal: give -o FILE, or redirect standard output to a file "
                        "or a pipe (-o - writes the image to the terminal anyway)");
}

void require_folder(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder.empty() ? "." : folder, error))
    throw Error(ErrorKind::NotFound, fmt::format("the output folder '{}' does not exist", folder.string()));
}

void require_folder_of(const std::string& file) {
  if (file != "-") require_folder(std::filesystem::path(file).parent_path());
}

Output::Output(const std::optional<std::string>& file) {
  if (!file || *file == "-") {
    stream_ = stdout;
    return;
  }
  file_ = *file;
  partial_ = file_->string() + ".partial-" + std::to_string(getpid());
  stream_ = std::fopen(partial_.c_str(), "wb");
  if (!stream_) fail("cannot create");
}

Output::~Output() {
  if (!file_ || finished_) return;
  if (stream_) std::fclose(stream_);
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void Output::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), stream_) != bytes.size()) fail("cannot write");
}

void Output::write(std::span<const uint8_t> bytes) {
  write(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void Output::finish() {
  if (std::fflush(stream_) != 0) fail("cannot write");
  if (!file_) return;
  const int closed = std::fclose(stream_);
  stream_ = nullptr;
  if (closed != 0) fail("cannot write");
  std::error_code error;
  std::filesystem::rename(partial_, *file_, error);
  if (error) {
    errno = error.value();
    fail("cannot rename the finished file to");
  }
  finished_ = true;
}

void Output::fail(const std::string& what) const {
  const std::string name = file_ ? fmt::format("'{}'", file_->string()) : "standard output";
  throw Error(ErrorKind::WriteFailed, fmt::format("{} {}: {}", what, name, std::strerror(errno)));
}

}  // namespace lp::cli
