#pragma once
// The test data committed in tests/data: real CC0 maps reduced to 256x128, meshes and models.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lp::test {

std::filesystem::path envmap_path(const std::string& file);      // tests/data/envmaps/<file>
inline constexpr int kRealMapWidth = 256, kRealMapHeight = 128;  // the size of every one of them
std::vector<std::string> real_envmap_files();                    // every file in tests/data/envmaps
std::filesystem::path mesh_path(const std::string& file);        // tests/data/meshes/<file>
std::vector<uint8_t> read_bytes(const std::filesystem::path& path);
// A committed input of a fuzz target's corpus: tests/fuzz/corpus/<target>/<file> (reproducers included).
std::filesystem::path fuzz_corpus_path(const std::string& target, const std::string& file);
// A committed model test input: tests/data/models/<file>.
std::filesystem::path model_path(const std::string& file);
// A model of Debian's assimp-testmodels (installed by scripts/setup): /usr/share/assimp/models/<file>,
// e.g. "glTF2/BoxTextured-glTF/BoxTextured.gltf".
std::filesystem::path assimp_model_path(const std::string& file);
// OBJ text of a bumpy n x n grid in the plane z = 0: (n + 1)^2 vertices, 2 n^2 triangles.
std::string grid_obj(int n);
// A PFM map of width x height pixels of grey 0.5: an upload of a known size (12 bytes a pixel).
std::vector<uint8_t> grey_map_pfm(int width, int height);
// A PNG of an n x n checkerboard of 1-pixel red and white squares.
std::string checker_png(int n);
// A PNG of width x height pixels all of the colour `rgb`.
std::string solid_png(int width, int height, std::array<uint8_t, 3> rgb);
// Writes a textured model into `folder`: quad.obj, the unit square in z = 0 facing +z (two triangles,
// UVs over the whole texture), and quad.mtl, one white material of Ns 0 with `albedo_png` as its map_Kd
// albedo.png and, if `normal_png` is not empty, it as its tangent-space normal map normal.png.
void write_textured_quad(const std::filesystem::path& folder, const std::string& albedo_png,
                         const std::string& normal_png = "");

}  // namespace lp::test
