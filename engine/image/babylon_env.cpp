#include "engine/image/babylon_env.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <nlohmann/json.hpp>

#include "engine/core/error.hpp"

namespace lp {

namespace {

using json = nlohmann::json;

constexpr std::array<uint8_t, 8> kMagic = {0x86, 0x16, 0x87, 0x96, 0xf6, 0xd6, 0x96, 0x36};

bool valid_width(int64_t width) {
  return width > 0 && std::has_single_bit(uint64_t(width));
}

json triple(const ShRgb& v) {
  return json::array({v[0], v[1], v[2]});
}

json polynomial_json(const BabylonSphericalPolynomial& p) {
  return {{"x", triple(p.x)},   {"y", triple(p.y)},   {"z", triple(p.z)},
          {"xx", triple(p.xx)}, {"yy", triple(p.yy)}, {"zz", triple(p.zz)},
          {"yz", triple(p.yz)}, {"zx", triple(p.zx)}, {"xy", triple(p.xy)}};
}

ShRgb read_triple(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 3) throw Error(ErrorKind::Corrupt, std::string(".env: irradiance.") + key);
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

BabylonSphericalPolynomial read_polynomial(const json& j) {
  BabylonSphericalPolynomial p;
  p.x = read_triple(j, "x"), p.y = read_triple(j, "y"), p.z = read_triple(j, "z");
  p.xx = read_triple(j, "xx"), p.yy = read_triple(j, "yy"), p.zz = read_triple(j, "zz");
  p.yz = read_triple(j, "yz"), p.zx = read_triple(j, "zx"), p.xy = read_triple(j, "xy");
  return p;
}

json manifest(const BabylonEnv& env) {
  json mipmaps = json::array();
  uint64_t position = 0;
  for (const auto& image : env.specular) {
    mipmaps.push_back({{"length", image.size()}, {"position", position}});
    position += image.size();
  }
  json m = {{"version", kBabylonEnvVersion},
            {"width", env.width},
            {"imageType", env.image_type},
            {"specular", {{"mipmaps", mipmaps}, {"lodGenerationScale", env.lod_generation_scale}}}};
  if (env.irradiance) m["irradiance"] = polynomial_json(*env.irradiance);
  return m;
}

// A count or offset of the manifest: a JSON integer at least 0 (a float is not converted).
uint64_t whole_number(const json& v) {
  if (!v.is_number_unsigned())
    throw Error(ErrorKind::Corrupt, ".env: expected a whole number, got " + v.dump());
  return v.get<uint64_t>();
}

// The images the manifest places in `payload` (the bytes after its NUL).
std::vector<std::vector<uint8_t>> read_images(const json& mipmaps, size_t count,
                                              std::span<const uint8_t> payload) {
  if (!mipmaps.is_array() || mipmaps.size() != count)
    throw Error(ErrorKind::Corrupt, ".env: expected " + std::to_string(count) + " specular images");
  std::vector<std::vector<uint8_t>> images;
  for (const json& m : mipmaps) {
    const uint64_t position = whole_number(m.at("position")), length = whole_number(m.at("length"));
    if (position > payload.size() || length > payload.size() - position)
      throw Error(ErrorKind::Corrupt, ".env: an image lies past the end of the file");
    images.emplace_back(payload.begin() + ptrdiff_t(position),
                        payload.begin() + ptrdiff_t(position + length));
  }
  return images;
}

}  // namespace

int babylon_env_levels(int width) {
  return std::bit_width(unsigned(width));
}

size_t babylon_env_images(int width) {
  return size_t(babylon_env_levels(width)) * 6;
}

std::vector<uint8_t> write_babylon_env(const BabylonEnv& env) {
  if (!valid_width(env.width))
    throw Error(ErrorKind::InvalidArgument,
                ".env: width " + std::to_string(env.width) + " is not a power of two");
  if (env.specular.size() != babylon_env_images(env.width))
    throw Error(ErrorKind::InvalidArgument,
                ".env: expected " + std::to_string(babylon_env_images(env.width)) + " specular images, got " +
                    std::to_string(env.specular.size()));
  const std::string text = manifest(env).dump();
  size_t size = kMagic.size() + text.size() + 1;
  for (const auto& image : env.specular) size += image.size();
  std::vector<uint8_t> out(size);  // the NUL after the manifest included
  auto at = std::copy(kMagic.begin(), kMagic.end(), out.begin());
  at = std::transform(text.begin(), text.end(), at, [](char c) { return uint8_t(c); }) + 1;
  for (const auto& image : env.specular) at = std::copy(image.begin(), image.end(), at);
  return out;
}

BabylonEnv read_babylon_env(std::span<const uint8_t> bytes) {
  if (bytes.size() < kMagic.size() || !std::equal(kMagic.begin(), kMagic.end(), bytes.begin()))
    throw Error(ErrorKind::Unsupported, "not a Babylon .env file");
  const auto text_begin = bytes.begin() + ptrdiff_t(kMagic.size());
  const auto nul = std::find(text_begin, bytes.end(), uint8_t{0});
  if (nul == bytes.end()) throw Error(ErrorKind::Corrupt, ".env: the manifest has no end");
  try {
    const json m = json::parse(text_begin, nul);
    if (whole_number(m.at("version")) != uint64_t(kBabylonEnvVersion))
      throw Error(ErrorKind::Corrupt, ".env: only version 2 is read");
    const uint64_t width = whole_number(m.at("width"));
    if (width > uint64_t(kBabylonEnvMaxWidth)) throw Error(ErrorKind::TooLarge, ".env: width over the limit");
    if (!valid_width(int64_t(width))) throw Error(ErrorKind::Corrupt, ".env: width is not a power of two");
    BabylonEnv env;
    env.width = int(width);
    env.image_type = m.at("imageType").get<std::string>();
    const json& specular = m.at("specular");
    env.lod_generation_scale = specular.value("lodGenerationScale", kBabylonLodGenerationScale);
    if (m.contains("irradiance") && !m["irradiance"].is_null())
      env.irradiance = read_polynomial(m["irradiance"]);
    const std::span<const uint8_t> payload(nul + 1, bytes.end());
    env.specular = read_images(specular.at("mipmaps"), babylon_env_images(env.width), payload);
    return env;
  } catch (const json::exception& e) {
    throw Error(ErrorKind::Corrupt, std::string(".env: manifest: ") + e.what());
  }
}

}  // namespace lp
