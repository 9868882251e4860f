#include "server/storage/content_hash.hpp"

#include <fmt/format.h>
#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <stdexcept>

namespace lp::server {
namespace {

constexpr size_t kBlockBytes = size_t(1) << 20;

struct ContextDeleter {
  void operator()(EVP_MD_CTX* context) const { EVP_MD_CTX_free(context); }
};

}  // namespace

struct ContentHasher::Context {
  std::unique_ptr<EVP_MD_CTX, ContextDeleter> evp{EVP_MD_CTX_new()};
};

ContentHasher::ContentHasher() : context_(std::make_unique<Context>()) {
  if (!context_->evp || EVP_DigestInit_ex(context_->evp.get(), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("cannot start a SHA-256");
}

ContentHasher::~ContentHasher() = default;

ContentHasher& ContentHasher::add(std::span<const std::byte> bytes) {
  if (EVP_DigestUpdate(context_->evp.get(), bytes.data(), bytes.size()) != 1)
    throw std::runtime_error("cannot update a SHA-256");
  return *this;
}

ContentHasher& ContentHasher::add_number(uint64_t value) {
  std::array<std::byte, 8> bytes;
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::byte((value >> (8 * i)) & 0xff);
  return add(bytes);
}

ContentHasher& ContentHasher::add_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.filename().string());
  std::vector<char> block(kBlockBytes);
  while (in) {
    in.read(block.data(), std::streamsize(block.size()));
    add(std::as_bytes(std::span(block.data(), size_t(in.gcount()))));
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path.filename().string());
  return *this;
}

std::string ContentHasher::hex() {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest;
  unsigned int size = 0;
  if (EVP_DigestFinal_ex(context_->evp.get(), digest.data(), &size) != 1)
    throw std::runtime_error("cannot finish a SHA-256");
  std::string out;
  out.reserve(2 * size);
  for (unsigned int i = 0; i < size; ++i) out += fmt::format("{:02x}", digest[i]);
  return out;
}

std::string content_hash(std::string_view bytes) {
  return ContentHasher().add(bytes).hex();
}

std::string file_content_hash(const std::filesystem::path& path) {
  return ContentHasher().add_file(path).hex();
}

std::string files_content_hash(const std::filesystem::path& folder, const std::vector<std::string>& files) {
  ContentHasher hasher;
  hasher.add_number(files.size());
  for (const auto& file : files) hasher.add_sized(file).add(file_content_hash(folder / file));
  return hasher.hex();
}

bool is_content_hash(std::string_view text) {
  return text.size() == kContentHashHexDigits && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

}  // namespace lp::server
