#pragma once
// The files a model refers to (glTF buffers and images, OBJ material libraries and textures), read
// relative to the model file's folder and never outside it: an absolute path, or one that leaves the
// folder by `..` or through a link, is refused. Every byte read counts against the model's byte limit.
// A model parsed from memory has no folder and may refer to no file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/model/model_memory.hpp"

namespace lp {

// A file as it was when a model was about to read it: a file whose stamp differs now has changed since.
struct FileStamp {
  std::filesystem::path path;  // canonical
  uintmax_t size = 0;
  std::filesystem::file_time_type modified{};
  bool operator==(const FileStamp&) const = default;

  // The file as it is now (size 0 and no time when it cannot be read).
  static FileStamp of(const std::filesystem::path& path);
};

class ModelFiles {
 public:
  // `folder` empty: a model from memory. `reserve` is told each file's file_load_bytes before it is read.
  ModelFiles(std::filesystem::path folder, int64_t max_bytes, ModelReserve reserve = {});

  // Counts bytes read by other means (the model file itself) against the limit.
  void count(int64_t bytes, const std::string& what);
  // Throws lp::Error: InvalidArgument (a path outside the folder, or any path for a model from
  // memory), NotFound, TooLarge.
  std::vector<uint8_t> read(const std::string& relative, const std::string& what);
  // A key naming the file's content for the texture cache: its canonical path, size and modification time.
  std::string cache_key(const std::string& relative);
  // Every file named through read() or cache_key(), stamped when first named, before it was read.
  const std::vector<FileStamp>& stamps() const { return stamps_; }

  // Reads the model file itself, whole (at most `max_bytes`), counting it like the others.
  std::vector<uint8_t> read_model(const std::filesystem::path& path, const std::string& what);
  // Reads a whole file (at most `max_bytes`). `reserve`, when given, is told its bytes first.
  static std::vector<uint8_t> read_file(const std::filesystem::path& path, int64_t max_bytes,
                                        const ModelReserve& reserve = {});

 private:
  // The file's path, stamped the first time.
  FileStamp resolve(const std::string& relative);

  std::filesystem::path folder_;  // canonical, or empty
  int64_t max_bytes_, bytes_ = 0;
  ModelReserve reserve_;
  std::vector<FileStamp> stamps_;
};

// A URI's %XX escapes decoded (glTF URIs are URI-encoded).
std::string decode_uri(const std::string& uri);

}  // namespace lp
