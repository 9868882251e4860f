#pragma once
// The container of a binary glTF (.glb): a 12-byte header (magic "glTF", version 2, the total length)
// and chunks of 8-byte header (length, type) and data, each a multiple of 4 bytes, the first JSON and an
// optional second BIN. Checked here, whole, before a glTF parser reads any of it.
#include <cstdint>
#include <span>
#include <string>

namespace lp::gltf {

// Whether the bytes start with the magic of a .glb (otherwise they are a .gltf's JSON).
bool is_glb(std::span<const uint8_t> bytes);

struct GlbChunks {
  std::span<const uint8_t> json;
  std::span<const uint8_t> bin;  // empty when the file has no BIN chunk
};

// The chunks of a .glb `name`, once the header's length is the file's size and every chunk lies whole
// within it. Throws lp::Error: Unsupported for a glTF 1.0 file, Corrupt naming what is wrong otherwise.
GlbChunks glb_chunks(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace lp::gltf
