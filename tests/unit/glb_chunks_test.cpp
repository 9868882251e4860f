// The .glb container checked before a glTF parser reads it: the committed quad's chunks are found, and
// each kind of broken header or chunk table is refused with an lp::Error naming it, the reproducer of a
// BIN chunk running 8 bytes past the file among them.
#include "engine/model/glb_chunks.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using Bytes = std::vector<uint8_t>;

// quad.glb: a 12-byte header, a JSON chunk of 1580 bytes at byte 12, a BIN chunk of 288 bytes at 1600.
constexpr size_t kBinChunkAt = 1600;

Bytes quad() {
  return test::read_bytes(test::model_path("quad.glb"));
}

void put_u32(Bytes& bytes, size_t at, uint32_t v) {
  std::memcpy(bytes.data() + at, &v, 4);
}

// The message of the lp::Error of kind `kind` that glb_chunks throws on `bytes`.
std::string refusal(const Bytes& bytes, ErrorKind kind = ErrorKind::Corrupt) {
  try {
    gltf::glb_chunks(bytes, "model.glb");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(GlbChunks, FindsTheQuadsJsonAndBinChunks) {
  const Bytes bytes = quad();
  ASSERT_EQ(bytes.size(), 1896u);
  const auto chunks = gltf::glb_chunks(bytes, "quad.glb");
  EXPECT_EQ(chunks.json.data(), bytes.data() + 20);
  EXPECT_EQ(chunks.json.size(), 1580u);
  EXPECT_EQ(chunks.bin.data(), bytes.data() + kBinChunkAt + 8);
  EXPECT_EQ(chunks.bin.size(), 288u);
}

TEST(GlbChunks, ABinChunkRunningPastTheFileIsRefused) {
  const Bytes bytes = test::read_bytes(test::fuzz_corpus_path("gltf", "bin_chunk_past_the_end.glb"));
  EXPECT_EQ(refusal(bytes),
            "glb model.glb: chunk 1 at byte 1600: its length 296 runs past the end of the file (288 bytes "
            "left)");
  try {
    load_gltf_memory(bytes, "model.glb", ModelLimits{});
    ADD_FAILURE() << "the model loaded";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
    EXPECT_NE(std::string(e.what()).find("runs past the end of the file"), std::string::npos) << e.what();
  }
}

TEST(GlbChunks, EachBrokenHeaderOrChunkIsNamed) {
  const std::vector<std::pair<std::function<void(Bytes&)>, std::string>> cases = {
      {[](Bytes& b) { b.resize(10); }, "shorter than its 12-byte header"},
      {[](Bytes& b) { put_u32(b, 4, 3); }, "version 3 is not 2"},
      {[](Bytes& b) { b.resize(b.size() - 4); },
       "its length is past the end of the file (1896 bytes declared"},
      {[](Bytes& b) { b.resize(b.size() + 4); }, "its length 1896 is not the file's size 1900"},
      {[](Bytes& b) { put_u32(b, 12, 1580 + 400); }, "chunk 0 at byte 12: its length 1980 runs past the end"},
      {[](Bytes& b) { put_u32(b, 12, 1578); }, "chunk 0 at byte 12: its length 1578 is not a multiple of 4"},
      {[](Bytes& b) { std::memcpy(b.data() + 16, "BIN", 4); }, "the first chunk is not JSON"},
      {[](Bytes& b) { put_u32(b, kBinChunkAt, 0xFFFFFFF8u); },
       "chunk 1 at byte 1600: its length 4294967288 runs past the end"},
      {[](Bytes& b) { std::memcpy(b.data() + kBinChunkAt + 4, "JSON", 4); },
       "chunk 1 is a second JSON chunk"},
      {[](Bytes& b) {
         put_u32(b, 8, uint32_t(b.size() + 4));
         b.insert(b.end(), {0, 0, 0, 0});
       },
       "chunk 2 at byte 1896: its 8-byte header runs past the end of the file"},
      {[](Bytes& b) {
         b.resize(12);
         put_u32(b, 8, 12);
       },
       "it has no chunks; the first must be JSON"},
  };
  for (const auto& [edit, message] : cases) {
    Bytes bytes = quad();
    edit(bytes);
    const std::string what = refusal(bytes);
    EXPECT_NE(what.find(message), std::string::npos) << what;
  }
}

TEST(GlbChunks, AGltf1BinaryIsUnsupported) {
  Bytes bytes = quad();
  put_u32(bytes, 4, 1);
  EXPECT_NE(refusal(bytes, ErrorKind::Unsupported).find("glTF 1.0"), std::string::npos);
}

TEST(GlbChunks, ChunksOfOtherTypesAfterBinAreSkipped) {
  Bytes bytes = quad();
  const Bytes extra = {4, 0, 0, 0, 'X', 'T', 'R', 'A', 1, 2, 3, 4};
  bytes.insert(bytes.end(), extra.begin(), extra.end());
  put_u32(bytes, 8, uint32_t(bytes.size()));
  const auto chunks = gltf::glb_chunks(bytes, "quad.glb");
  EXPECT_EQ(chunks.bin.size(), 288u);
  std::memcpy(bytes.data() + kBinChunkAt + 4, "XTRA", 4);  // now BIN comes third
  std::memcpy(bytes.data() + 1896 + 4, "BIN\0", 4);
  EXPECT_NE(refusal(bytes).find("chunk 2 is BIN; only the second chunk may be"), std::string::npos);
}

}  // namespace
}  // namespace lp
