#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "engine/image/image_io.hpp"

namespace lp::test {

std::filesystem::path shared_data() {
  return LIGHTPROBE_SHARED_DATA;
}

std::filesystem::path envmap_path(const std::string& file) {
  return shared_data() / "envmaps" / file;
}

std::vector<std::string> real_envmap_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(shared_data() / "envmaps"))
    if (e.is_regular_file()) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::filesystem::path fuzz_corpus_path(const std::string& target, const std::string& file) {
  return std::filesystem::path(LIGHTPROBE_FUZZ_CORPUS) / target / file;
}

std::filesystem::path model_path(const std::string& file) {
  return std::filesystem::path(LIGHTPROBE_TEST_DATA) / "models" / file;
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

std::string checker_png(int n) {
  std::vector<uint8_t> rgb;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const uint8_t other = (x + y) % 2 ? 255 : 30;
      rgb.insert(rgb.end(), {255, other, other});
    }
  const auto png = encode_png_rgb8(rgb, n, n);
  return {png.begin(), png.end()};
}

}  // namespace lp::test
