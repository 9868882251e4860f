#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "engine/image/image_io.hpp"

namespace lp::test {

namespace {
std::filesystem::path test_data() {
  return LIGHTPROBE_TEST_DATA;
}
}  // namespace

std::filesystem::path envmap_path(const std::string& file) {
  return test_data() / "envmaps" / file;
}

std::filesystem::path mesh_path(const std::string& file) {
  return test_data() / "meshes" / file;
}

std::vector<std::string> real_envmap_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(test_data() / "envmaps"))
    if (e.is_regular_file()) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::filesystem::path fuzz_corpus_path(const std::string& target, const std::string& file) {
  return std::filesystem::path(LIGHTPROBE_FUZZ_CORPUS) / target / file;
}

std::filesystem::path model_path(const std::string& file) {
  return test_data() / "models" / file;
}

std::filesystem::path assimp_model_path(const std::string& file) {
  return std::filesystem::path("/usr/share/assimp/models") / file;
}

std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string grid_obj(int n) {
  std::ostringstream out;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) out << "v " << x << ' ' << y << ' ' << ((x * 7 + y * 13) % 5) * 0.1 << '\n';
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 1, d = c + 1;
      out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
  return out.str();
}

std::vector<uint8_t> grey_map_pfm(int width, int height) {
  Image image(width, height);
  std::fill(image.data().begin(), image.data().end(), 0.5f);
  return write_pfm(image);
}

namespace {

std::string png(const std::vector<uint8_t>& rgb, int width, int height) {
  const auto bytes = encode_png_rgb8(rgb, width, height);
  return {bytes.begin(), bytes.end()};
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  if (!out.write(bytes.data(), std::streamsize(bytes.size())))
    throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

std::string checker_png(int n) {
  std::vector<uint8_t> rgb;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const uint8_t other = (x + y) % 2 ? 255 : 30;
      rgb.insert(rgb.end(), {255, other, other});
    }
  return png(rgb, n, n);
}

std::string solid_png(int width, int height, std::array<uint8_t, 3> rgb) {
  std::vector<uint8_t> texels;
  for (int i = 0; i < width * height; ++i) texels.insert(texels.end(), rgb.begin(), rgb.end());
  return png(texels, width, height);
}

void write_textured_quad(const std::filesystem::path& folder, const std::string& albedo_png,
                         const std::string& normal_png) {
  write_file(folder / "quad.obj",
             "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
             "vn 0 0 1\nusemtl m\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
  write_file(folder / "quad.mtl", "newmtl m\nKd 1 1 1\nNs 0\nmap_Kd albedo.png\n" +
                                      std::string(normal_png.empty() ? "" : "norm normal.png\n"));
  write_file(folder / "albedo.png", albedo_png);
  if (!normal_png.empty()) write_file(folder / "normal.png", normal_png);
}

}  // namespace lp::test
