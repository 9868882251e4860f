#pragma once
// A mesh bundle (mesh_bundles.hpp) as a tar archive (POSIX pax, written with libarchive): its files by
// their paths inside the bundle, as they are on disk now, with fixed times and modes. Workers unpack it
// with unpack_archive and check its hash.
#include <cstdint>
#include <vector>

#include "server/scale_out/mesh_bundles.hpp"

namespace lp::server {

// The most bytes the tar of `files` files of `file_bytes` bytes together takes: each member's headers
// (a pax header for a long path too) and padding, and the archive's end.
int64_t bundle_tar_bytes(int64_t file_bytes, int64_t files);

struct BundleSize {
  int64_t file_bytes = 0;          // the files together, as they are now
  int64_t largest_file_bytes = 0;  // read one at a time while writing
  int64_t tar_bytes = 0;           // at most, by bundle_tar_bytes
};
// Throws lp::Error (NotFound) when a file is gone.
BundleSize bundle_size(const MeshBundle& bundle);

// The bundle's tar. Throws lp::Error when a file is gone or grew past `size`'s largest file,
// std::runtime_error when libarchive fails.
std::vector<uint8_t> write_bundle_tar(const MeshBundle& bundle, const BundleSize& size);

}  // namespace lp::server
