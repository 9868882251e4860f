#include "engine/model/gltf_material_lobes.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "engine/core/error.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// One extension object of a material: its numbers, colours and textures, each checked and named.
class ExtensionReader {
 public:
  ExtensionReader(const tinygltf::Value& object, std::string what, const TextureReader& texture)
      : o_(object), what_(std::move(what)), texture_(texture) {
    if (!o_.IsObject()) fail("", "is not an object");
  }

  // The number `key` in [lo, hi], or `fallback` when absent.
  float number(const char* key, float fallback, double lo, double hi) const {
    if (!o_.Has(key)) return fallback;
    const tinygltf::Value& v = o_.Get(key);
    const double x = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
    if (!(x >= lo && x <= hi)) fail(key, fmt::format("is not a number in [{}, {}]", lo, hi));
    return float(x);
  }

  // A colour of three numbers in [0, hi].
  Rgb color(const char* key, Rgb fallback, double hi = 1) const {
    if (!o_.Has(key)) return fallback;
    const tinygltf::Value& v = o_.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) fail(key, "is not an array of three numbers");
    float c[3];
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& x = v.Get(i);
      const double d = x.IsNumber() ? x.GetNumberAsDouble() : std::nan("");
      if (!(d >= 0 && d <= hi)) fail(key, fmt::format("has a component not in [0, {}]", hi));
      c[i] = float(d);
    }
    return {c[0], c[1], c[2]};
  }

  std::optional<TextureBinding> texture(const char* key, ColorSpace space, float* scale = nullptr) const {
    if (!o_.Has(key)) return std::nullopt;
    const tinygltf::Value& v = o_.Get(key);
    if (!v.IsObject()) fail(key, "is not an object");
    tinygltf::TextureInfo info;
    info.index = integer(v, "index", key, -1);
    if (info.index < 0) fail(key, "has no texture index");
    info.texCoord = integer(v, "texCoord", key, 0);
    if (v.Has("extensions")) {
      const tinygltf::Value& e = v.Get("extensions");
      if (!e.IsObject()) fail(key, "extensions is not an object");
      for (const std::string& name : e.Keys()) info.extensions[name] = e.Get(name);
    }
    if (scale) {
      *scale = 1;
      if (v.Has("scale")) {
        const tinygltf::Value& s = v.Get("scale");
        if (!s.IsNumber() || !std::isfinite(s.GetNumberAsDouble())) fail(key, "scale is not a finite number");
        *scale = float(s.GetNumberAsDouble());
      }
    }
    return texture_(info, space, name(key));
  }

 private:
  int integer(const tinygltf::Value& v, const char* key, const char* parent, int fallback) const {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& x = v.Get(key);
    if (!x.IsInt() || x.GetNumberAsInt() < 0) fail(parent, fmt::format("{} is not an index", key));
    return x.GetNumberAsInt();
  }
  std::string name(const char* key) const { return *key ? what_ + " " + key : what_; }
  [[noreturn]] void fail(const char* key, const std::string& problem) const {
    throw Error(ErrorKind::Corrupt, name(key) + " " + problem);
  }

  const tinygltf::Value& o_;
  std::string what_;
  const TextureReader& texture_;
};

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  const auto it = m.extensions.find(name);
  return it == m.extensions.end() ? nullptr : &it->second;
}

void read_ior(const ExtensionReader& e, MaterialLobes& l) {
  l.ior = e.number("ior", l.ior, 0, 10);
  if (l.ior > 0 && l.ior < 1) l.ior = 1;  // only 0 (a perfect reflector) lies below 1 in the extension
}

void read_specular(const ExtensionReader& e, MaterialLobes& l) {
  l.specular_factor = e.number("specularFactor", l.specular_factor, 0, 1);
  l.specular = e.texture("specularTexture", ColorSpace::Linear);
  // specularColorFactor may exceed 1: F0 is clamped to 1 after the ior's F0 scales it.
  l.specular_color_factor = e.color("specularColorFactor", l.specular_color_factor, kInf);
  l.specular_color = e.texture("specularColorTexture", ColorSpace::Srgb);
}

void read_transmission(const ExtensionReader& e, MaterialLobes& l) {
  l.transmission_factor = e.number("transmissionFactor", l.transmission_factor, 0, 1);
  l.transmission = e.texture("transmissionTexture", ColorSpace::Linear);
}

void read_volume(const ExtensionReader& e, MaterialLobes& l) {
  l.thickness_factor = e.number("thicknessFactor", l.thickness_factor, 0, kInf);
  l.thickness = e.texture("thicknessTexture", ColorSpace::Linear);
  l.attenuation_distance =
      e.number("attenuationDistance", l.attenuation_distance, std::numeric_limits<double>::min(), kInf);
  l.attenuation_color = e.color("attenuationColor", l.attenuation_color);
}

void read_clearcoat(const ExtensionReader& e, MaterialLobes& l) {
  l.clearcoat_factor = e.number("clearcoatFactor", l.clearcoat_factor, 0, 1);
  l.clearcoat = e.texture("clearcoatTexture", ColorSpace::Linear);
  l.clearcoat_roughness_factor = e.number("clearcoatRoughnessFactor", l.clearcoat_roughness_factor, 0, 1);
  l.clearcoat_roughness = e.texture("clearcoatRoughnessTexture", ColorSpace::Linear);
  l.clearcoat_normal = e.texture("clearcoatNormalTexture", ColorSpace::Linear, &l.clearcoat_normal_scale);
}

void read_sheen(const ExtensionReader& e, MaterialLobes& l) {
  l.sheen_color_factor = e.color("sheenColorFactor", l.sheen_color_factor);
  l.sheen_color = e.texture("sheenColorTexture", ColorSpace::Srgb);
  l.sheen_roughness_factor = e.number("sheenRoughnessFactor", l.sheen_roughness_factor, 0, 1);
  l.sheen_roughness = e.texture("sheenRoughnessTexture", ColorSpace::Linear);
}

}  // namespace

std::optional<MaterialLobes> read_material_lobes(const tinygltf::Material& material, const std::string& what,
                                                 const TextureReader& texture) {
  using Read = void (*)(const ExtensionReader&, MaterialLobes&);
  static const std::pair<const char*, Read> kExtensions[] = {
      {"KHR_materials_ior", read_ior},
      {"KHR_materials_specular", read_specular},
      {"KHR_materials_transmission", read_transmission},
      {"KHR_materials_volume", read_volume},
      {"KHR_materials_clearcoat", read_clearcoat},
      {"KHR_materials_sheen", read_sheen},
  };
  std::optional<MaterialLobes> lobes;
  for (const auto& [name, read] : kExtensions)
    if (const tinygltf::Value* v = extension(material, name)) {
      if (!lobes) lobes.emplace();
      read(ExtensionReader(*v, what + " " + name, texture), *lobes);
    }
  return lobes;
}

}  // namespace lp::gltf
