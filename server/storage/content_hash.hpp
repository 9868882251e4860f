#pragma once
// Content hashes: SHA-256 (OpenSSL's libcrypto), written as 64 lowercase hex digits. Whatever decides that
// two things hold the same content (a map's pixels, a model's files, a mesh bundle) names it by one of
// these, so that no one can make other content that passes for it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lp::server {

inline constexpr size_t kContentHashHexDigits = 64;

// A SHA-256 fed piece by piece. A piece of varying length goes in after its length (add_sized), so that
// two sequences of pieces cannot run into each other and hash alike.
class ContentHasher {
 public:
  ContentHasher();
  ~ContentHasher();
  ContentHasher(const ContentHasher&) = delete;
  ContentHasher& operator=(const ContentHasher&) = delete;

  ContentHasher& add(std::span<const std::byte> bytes);
  ContentHasher& add(std::string_view bytes) { return add(std::as_bytes(std::span(bytes))); }
  ContentHasher& add_number(uint64_t value);  // 8 bytes, little-endian
  ContentHasher& add_sized(std::string_view bytes) { return add_number(bytes.size()).add(bytes); }
  // A file's bytes, a block at a time. Throws std::runtime_error naming the file when it cannot be read.
  ContentHasher& add_file(const std::filesystem::path& path);

  // The hash of everything added; the hasher is spent.
  std::string hex();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

std::string content_hash(std::string_view bytes);
std::string file_content_hash(const std::filesystem::path& path);

// The hash of files by their names: each '/'-separated name inside `folder` and the hash of its bytes, in
// the order given. Throws std::runtime_error when a file cannot be read.
std::string files_content_hash(const std::filesystem::path& folder, const std::vector<std::string>& files);

// Whether `text` is a content hash in hex.
bool is_content_hash(std::string_view text);

}  // namespace lp::server
