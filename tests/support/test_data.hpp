#pragma once
// Where the shared test data lives (../shared/data beside the repository).
#include <filesystem>
#include <string>
#include <vector>

namespace lp::test {

std::filesystem::path shared_data();                         // ../shared/data
std::filesystem::path envmap_path(const std::string& file);  // ../shared/data/envmaps/<file>
std::vector<std::string> real_envmap_files();                // every file in ../shared/data/envmaps
std::vector<uint8_t> read_bytes(const std::filesystem::path& path);
// A committed input of a fuzz target's corpus: tests/fuzz/corpus/<target>/<file> (reproducers included).
std::filesystem::path fuzz_corpus_path(const std::string& target, const std::string& file);
// A committed model test input: tests/data/models/<file>.
std::filesystem::path model_path(const std::string& file);
// OBJ text of a bumpy n x n grid in the plane z = 0: (n + 1)^2 vertices, 2 n^2 triangles.
std::string grid_obj(int n);
// A PNG of an n x n checkerboard of 1-pixel red and white squares.
std::string checker_png(int n);

}  // namespace lp::test
