#include "engine/model/glb_chunks.hpp"

#include <fmt/format.h>

#include <cstring>

#include "engine/core/error.hpp"

namespace lp::gltf {
namespace {

constexpr size_t kHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;
constexpr uint32_t kJson = 0x4E4F534A;  // "JSON" read as a little-endian number
constexpr uint32_t kBin = 0x004E4942;   // "BIN\0"

uint32_t read_u32(std::span<const uint8_t> bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // glTF is little-endian, as are the machines we build for
}

class ChunkReader {
 public:
  ChunkReader(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void corrupt(const std::string& why) const {
    throw Error(ErrorKind::Corrupt, "glb " + name_ + ": " + why);
  }

  void header() const {
    if (bytes_.size() < kHeaderBytes) corrupt("shorter than its 12-byte header");
    const uint32_t version = read_u32(bytes_, 4);
    if (version == 1)
      throw Error(ErrorKind::Unsupported,
                  "glb " + name_ + ": a binary glTF 1.0 file (header version 1): only glTF 2.0 is supported");
    if (version != 2) corrupt(fmt::format("version {} is not 2", version));
    const uint32_t length = read_u32(bytes_, 8);
    if (length > bytes_.size())
      corrupt(fmt::format("its length is past the end of the file ({} bytes declared, {} present)", length,
                          bytes_.size()));
    if (length != bytes_.size())
      corrupt(fmt::format("its length {} is not the file's size {}", length, bytes_.size()));
  }

  bool done() const { return at_ == bytes_.size(); }

  // The next chunk's type and data, checked to lie within the file.
  std::pair<uint32_t, std::span<const uint8_t>> next() {
    const size_t index = chunks_++;
    if (bytes_.size() - at_ < kChunkHeaderBytes)
      corrupt(
          fmt::format("chunk {} at byte {}: its 8-byte header runs past the end of the file", index, at_));
    const uint32_t length = read_u32(bytes_, at_);
    const uint32_t type = read_u32(bytes_, at_ + 4);
    const size_t start = at_ + kChunkHeaderBytes;
    if (length > bytes_.size() - start)
      corrupt(fmt::format("chunk {} at byte {}: its length {} runs past the end of the file ({} bytes left)",
                          index, at_, length, bytes_.size() - start));
    if (length % 4 != 0)
      corrupt(fmt::format("chunk {} at byte {}: its length {} is not a multiple of 4", index, at_, length));
    at_ = start + length;
    return {type, bytes_.subspan(start, length)};
  }

 private:
  std::span<const uint8_t> bytes_;
  const std::string& name_;
  size_t at_ = kHeaderBytes;
  int chunks_ = 0;
};

}  // namespace

bool is_glb(std::span<const uint8_t> bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

GlbChunks glb_chunks(std::span<const uint8_t> bytes, const std::string& name) {
  ChunkReader reader(bytes, name);
  reader.header();
  GlbChunks out;
  if (reader.done()) reader.corrupt("it has no chunks; the first must be JSON");
  const auto [first, json] = reader.next();
  if (first != kJson) reader.corrupt("the first chunk is not JSON");
  if (json.empty()) reader.corrupt("the JSON chunk is empty");
  out.json = json;
  for (int index = 1; !reader.done(); ++index) {
    const auto [type, data] = reader.next();
    if (type == kJson) reader.corrupt(fmt::format("chunk {} is a second JSON chunk", index));
    if (type != kBin) continue;  // chunks of other types are skipped, as the specification asks
    if (index != 1) reader.corrupt(fmt::format("chunk {} is BIN; only the second chunk may be", index));
    out.bin = data;
  }
  return out;
}

}  // namespace lp::gltf
