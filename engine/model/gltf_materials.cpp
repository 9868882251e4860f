#include "engine/model/gltf_materials.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "engine/core/error.hpp"
#include "engine/model/gltf_accessor.hpp"
#include "engine/model/gltf_material_lobes.hpp"
#include "engine/model/model_files.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

[[noreturn]] void corrupt(const std::string& what, const std::string& problem) {
  throw Error(ErrorKind::Corrupt, what + " " + problem);
}

float factor(double v, double lo, double hi, const std::string& what) {
  if (!std::isfinite(v) || v < lo || v > hi) corrupt(what, fmt::format("{} is not in [{}, {}]", v, lo, hi));
  return float(v);
}

std::vector<float> factors(const std::vector<double>& v, size_t n, double hi, const std::string& what) {
  if (v.size() != n) corrupt(what, fmt::format("has {} numbers, not {}", v.size(), n));
  std::vector<float> out;
  for (double x : v) out.push_back(factor(x, 0, hi, what));
  return out;
}

WrapMode wrap_mode(int mode, const std::string& what) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT:
      return WrapMode::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return WrapMode::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return WrapMode::MirroredRepeat;
    default:
      corrupt(what, fmt::format("has the unknown wrap mode {}", mode));
  }
}

float number(const tinygltf::Value& v, const std::string& what) {
  if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) corrupt(what, "is not a finite number");
  return float(v.GetNumberAsDouble());
}

Point2 pair(const tinygltf::Value& v, const std::string& what) {
  if (!v.IsArray() || v.ArrayLen() != 2) corrupt(what, "is not an array of two numbers");
  return {number(v.Get(0), what), number(v.Get(1), what)};
}

// KHR_texture_transform of a texture reference, and the texture coordinate set it selects.
TextureTransform transform(const tinygltf::ExtensionMap& extensions, int& tex_coord,
                           const std::string& what) {
  TextureTransform t;
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end()) return t;
  const tinygltf::Value& e = it->second;
  const std::string name = what + " KHR_texture_transform";
  if (!e.IsObject()) corrupt(name, "is not an object");
  if (e.Has("offset")) t.offset = pair(e.Get("offset"), name + " offset");
  if (e.Has("rotation")) t.rotation = number(e.Get("rotation"), name + " rotation");
  if (e.Has("scale")) t.scale = pair(e.Get("scale"), name + " scale");
  if (e.Has("texCoord")) {
    const tinygltf::Value& c = e.Get("texCoord");
    if (!c.IsInt()) corrupt(name + " texCoord", "is not an integer");
    tex_coord = c.GetNumberAsInt();
  }
  return t;
}

AlphaMode alpha_mode(const std::string& mode, const std::string& what) {
  if (mode.empty() || mode == "OPAQUE") return AlphaMode::Opaque;
  if (mode == "MASK") return AlphaMode::Mask;
  if (mode == "BLEND") return AlphaMode::Blend;
  corrupt(what + " alphaMode", fmt::format("'{}' is not OPAQUE, MASK or BLEND", mode.substr(0, 32)));
}

// alphaMode, alphaCutoff, doubleSided and KHR_materials_emissive_strength.
void read_coverage(const tinygltf::Material& m, ModelMaterial& out, const std::string& what) {
  out.alpha_mode = alpha_mode(m.alphaMode, what);
  out.alpha_cutoff = factor(m.alphaCutoff, 0, std::numeric_limits<float>::max(), what + " alphaCutoff");
  out.double_sided = m.doubleSided;
  const auto it = m.extensions.find("KHR_materials_emissive_strength");
  if (it != m.extensions.end() && it->second.Has("emissiveStrength"))
    out.emissive_strength = factor(number(it->second.Get("emissiveStrength"), what + " emissiveStrength"), 0,
                                   std::numeric_limits<float>::max(), what + " emissiveStrength");
}

class MaterialReader {
 public:
  MaterialReader(const tinygltf::Model& model, ModelTextures& textures)
      : model_(model), textures_(textures) {}

  // The texture a material refers to, with its sampler and transform.
  template <class Info>
  std::optional<TextureBinding> binding(const Info& info, ColorSpace space, const std::string& what) {
    if (info.index < 0) return std::nullopt;
    if (size_t(info.index) >= model_.textures.size())
      corrupt(what, fmt::format("refers to texture {}, which does not exist", info.index));
    int tex_coord = info.texCoord;
    TextureBinding b;
    b.transform = transform(info.extensions, tex_coord, what);
    if (tex_coord != 0 && tex_coord != 1)
      throw Error(ErrorKind::Unsupported,
                  fmt::format("{} uses texture coordinates {}: only TEXCOORD_0 and TEXCOORD_1 are supported",
                              what, tex_coord));
    b.tex_coord = tex_coord;
    const tinygltf::Texture& t = model_.textures[size_t(info.index)];
    const std::string name = fmt::format("texture {}", info.index);
    if (t.sampler >= 0) {
      if (size_t(t.sampler) >= model_.samplers.size())
        corrupt(name, fmt::format("refers to sampler {}, which does not exist", t.sampler));
      const tinygltf::Sampler& s = model_.samplers[size_t(t.sampler)];
      const std::string sampler = fmt::format("sampler {}", t.sampler);
      b.sampler = {wrap_mode(s.wrapS, sampler), wrap_mode(s.wrapT, sampler)};
    }
    if (t.source < 0 || size_t(t.source) >= model_.images.size())
      corrupt(name, fmt::format("refers to image {}, which does not exist", t.source));
    b.texture = image(t.source, space);
    return b;
  }

  ModelMaterial material(size_t index) {
    const tinygltf::Material& m = model_.materials[index];
    const std::string what = fmt::format("material {}", index);
    const auto& pbr = m.pbrMetallicRoughness;
    ModelMaterial out;
    out.name = m.name;
    const auto base = factors(pbr.baseColorFactor, 4, 1, what + " baseColorFactor");
    out.base_color_factor = {base[0], base[1], base[2], base[3]};
    out.base_color = binding(pbr.baseColorTexture, ColorSpace::Srgb, what + " baseColorTexture");
    out.metallic_factor = factor(pbr.metallicFactor, 0, 1, what + " metallicFactor");
    out.roughness_factor = factor(pbr.roughnessFactor, 0, 1, what + " roughnessFactor");
    out.metallic_roughness =
        binding(pbr.metallicRoughnessTexture, ColorSpace::Linear, what + " metallicRoughnessTexture");
    out.normal = binding(m.normalTexture, ColorSpace::Linear, what + " normalTexture");
    if (!std::isfinite(m.normalTexture.scale)) corrupt(what + " normalTexture scale", "is not finite");
    out.normal_scale = float(m.normalTexture.scale);
    if (!m.emissiveFactor.empty()) {
      const auto e = factors(m.emissiveFactor, 3, 1, what + " emissiveFactor");
      out.emissive_factor = {e[0], e[1], e[2]};
    }
    out.emissive = binding(m.emissiveTexture, ColorSpace::Srgb, what + " emissiveTexture");
    out.lobes = read_material_lobes(
        m, what, [this](const tinygltf::TextureInfo& info, ColorSpace space, const std::string& name) {
          return binding(info, space, name);
        });
    read_coverage(m, out, what);
    return out;
  }

 private:
  std::shared_ptr<const Texture> image(int index, ColorSpace space) {
    const tinygltf::Image& i = model_.images[size_t(index)];
    const std::string what = fmt::format("image {}", index);
    if (i.as_is) return textures_.embedded(index, i.image, space, what);  // a data URI, decoded by tinygltf
    if (i.bufferView >= 0)
      return textures_.embedded(index, buffer_view_bytes(model_, i.bufferView, what), space, what);
    if (i.uri.empty()) corrupt(what, "has neither a uri nor a buffer view");
    return textures_.file(decode_uri(i.uri), space, what);
  }

  const tinygltf::Model& model_;
  ModelTextures& textures_;
};

}  // namespace

ModelMaterial default_material() {
  ModelMaterial m;
  m.name = "default";
  return m;
}

std::vector<ModelMaterial> read_materials(const tinygltf::Model& model, ModelTextures& textures) {
  MaterialReader reader(model, textures);
  std::vector<ModelMaterial> out;
  for (size_t i = 0; i < model.materials.size(); ++i) out.push_back(reader.material(i));
  return out;
}

}  // namespace lp::gltf
