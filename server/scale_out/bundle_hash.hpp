#pragma once
// The content hash of a mesh bundle (a model file and every file it was read from, mesh_bundles.hpp),
// in the family of a map's (maps/envmap_content_hash.hpp): a SHA-256 (storage/content_hash.hpp) over each
// file's path inside the bundle and its bytes, taken in the order of the paths. Where the folder lies and
// the order the files are listed in do not change it; any byte, path or file more or less does. Written as
// 64 hex digits and "-bundle", which a map's hash ("-WIDTHxHEIGHT") never ends in.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lp::server {

// The hash of the files `files` ('/'-separated paths inside `folder`). Throws std::runtime_error when a
// file cannot be read.
std::string bundle_hash(const std::filesystem::path& folder, std::vector<std::string> files);

// Whether `text` has the form of a bundle hash (so it is safe as a folder name).
bool is_bundle_hash(std::string_view text);

}  // namespace lp::server
