#pragma once
// The files a finished prefiltered chain is delivered as, and the conventions written into them.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "api/prefilter_request.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {

// "level0.exr", "level1.exr", ... (format exr: a cube's level is the strip of its faces) or
// "prefiltered.ktx2" (format ktx2: a cube map for the cube projection, a 2D texture for the others).
std::vector<std::string> prefilter_file_names(const PrefilterRequest& request);
const char* prefilter_file_mime_type(PrefilterFormat format);

// How to read a chain: (name, text) pairs, in the status JSON's "convention" and, as "lightprobe.NAME",
// in a KTX2 file's metadata. The cube and the cross add "cube_faces".
std::vector<std::pair<std::string, std::string>> prefilter_conventions(const PrefilterRequest& request);

// The bytes encoding the file `name` takes at most (its encoder's buffers included); 404 for a name
// that is not one of the chain's files.
int64_t prefilter_file_bytes(const PrefilterRequest& request, const std::string& name);
// The level a preview path names ("0" .. "levels - 1", decimal as written by std::to_string); 404 for
// any other text.
int prefilter_level_index(const PrefilterRequest& request, const std::string& text);

// A strip of six N x N faces side by side (6N x N) as KTX2 lays out a cube map's level: the faces one
// below the other (N x 6N).
Image stacked_faces(const Image& strip);

std::vector<uint8_t> encode_prefilter_file(const PrefilteredChain& chain, const PrefilterRequest& request,
                                           const std::string& name);

}  // namespace lp::api
