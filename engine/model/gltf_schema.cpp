#include "engine/model/gltf_schema.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/model/glb_chunks.hpp"

namespace lp::gltf {
namespace {

using json = nlohmann::json;

class Checker {
 public:
  explicit Checker(const std::string& name) : name_(name) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw Error(ErrorKind::Corrupt, fmt::format("glTF {}: {} {}", name_, path, problem));
  }

  const json* field(const json& o, const char* key) const {
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }
  static std::string at(const std::string& path, const char* key) {
    return path.empty() ? key : path + "." + key;
  }

  void object(const json& v, const std::string& path) const {
    if (!v.is_object()) fail(path, "must be an object");
    if (const json* n = field(v, "name"); n && !n->is_string()) fail(at(path, "name"), "must be a string");
    if (const json* e = field(v, "extensions")) {
      if (!e->is_object()) fail(at(path, "extensions"), "must be an object");
      for (const auto& [key, value] : e->items())
        if (!value.is_object()) fail(at(path, "extensions") + "." + key.substr(0, 64), "must be an object");
    }
  }
  void index(const json& o, const char* key, const std::string& path, bool required = false) const {
    const json* v = field(o, key);
    if (!v) {
      if (required) fail(at(path, key), "is missing");
      return;
    }
    if (!v->is_number_unsigned()) fail(at(path, key), "must be a non-negative integer");
  }
  void number(const json& o, const char* key, const std::string& path) const {
    if (const json* v = field(o, key); v && !v->is_number()) fail(at(path, key), "must be a number");
  }
  void boolean(const json& o, const char* key, const std::string& path) const {
    if (const json* v = field(o, key); v && !v->is_boolean()) fail(at(path, key), "must be a boolean");
  }
  void string(const json& o, const char* key, const std::string& path) const {
    if (const json* v = field(o, key); v && !v->is_string()) fail(at(path, key), "must be a string");
  }
  template <class Element>
  void array(const json& o, const char* key, const std::string& path, Element&& element) const {
    const json* v = field(o, key);
    if (!v) return;
    if (!v->is_array()) fail(at(path, key), "must be an array");
    for (size_t i = 0; i < v->size(); ++i) element((*v)[i], fmt::format("{}[{}]", at(path, key), i));
  }
  void numbers(const json& o, const char* key, const std::string& path) const {
    array(o, key, path, [&](const json& v, const std::string& p) {
      if (!v.is_number()) fail(p, "must be a number");
    });
  }
  void indices(const json& o, const char* key, const std::string& path) const {
    array(o, key, path, [&](const json& v, const std::string& p) {
      if (!v.is_number_unsigned()) fail(p, "must be a non-negative integer");
    });
  }
  void strings(const json& o, const char* key, const std::string& path) const {
    array(o, key, path, [&](const json& v, const std::string& p) {
      if (!v.is_string()) fail(p, "must be a string");
    });
  }
  // An object-valued property checked by `check` when present.
  template <class Check>
  void child(const json& o, const char* key, const std::string& path, Check&& check) const {
    if (const json* v = field(o, key)) {
      object(*v, at(path, key));
      check(*v, at(path, key));
    }
  }

  void texture_info(const json& o, const std::string& path) const {
    index(o, "index", path, true);
    index(o, "texCoord", path);
    number(o, "scale", path);
    number(o, "strength", path);
    if (const json* e = field(o, "extensions"))
      child(*e, "KHR_texture_transform", at(path, "extensions"), [&](const json& t, const std::string& p) {
        numbers(t, "offset", p);
        number(t, "rotation", p);
        numbers(t, "scale", p);
        index(t, "texCoord", p);
      });
  }

  void material(const json& m, const std::string& path) const {
    const auto info = [&](const json& v, const std::string& p) { texture_info(v, p); };
    child(m, "pbrMetallicRoughness", path, [&](const json& pbr, const std::string& p) {
      numbers(pbr, "baseColorFactor", p);
      child(pbr, "baseColorTexture", p, info);
      number(pbr, "metallicFactor", p);
      number(pbr, "roughnessFactor", p);
      child(pbr, "metallicRoughnessTexture", p, info);
    });
    child(m, "normalTexture", path, info);
    child(m, "occlusionTexture", path, info);
    child(m, "emissiveTexture", path, info);
    numbers(m, "emissiveFactor", path);
    string(m, "alphaMode", path);
    number(m, "alphaCutoff", path);
    boolean(m, "doubleSided", path);
  }

  void primitive(const json& p, const std::string& path) const {
    const json* attributes = field(p, "attributes");
    if (!attributes) fail(at(path, "attributes"), "is missing");
    object(*attributes, at(path, "attributes"));
    for (const auto& [key, value] : attributes->items())
      if (!value.is_number_unsigned())
        fail(at(path, "attributes") + "." + key.substr(0, 64), "must be a non-negative integer");
    index(p, "indices", path);
    index(p, "material", path);
    index(p, "mode", path);
  }

  // Each element of the top-level array `key` an object, checked by `check`.
  template <class Check>
  void objects(const json& root, const char* key, Check&& check) const {
    array(root, key, "", [&](const json& v, const std::string& p) {
      object(v, p);
      check(v, p);
    });
  }

  // glTF 1.0 differs from 2.0 throughout: a 1.0 file (asset.version "1.0", or the number 1 that early
  // exporters wrote) is refused as such, not for the first property whose type changed.
  void version(const json& root) const {
    const json* asset = field(root, "asset");
    const json* v = asset && asset->is_object() ? field(*asset, "version") : nullptr;
    if (!v) return;
    const bool one = v->is_string() ? v->get_ref<const std::string&>().starts_with("1.")
                                    : v->is_number() && v->get<double>() >= 1 && v->get<double>() < 2;
    if (one)
      throw Error(ErrorKind::Unsupported,
                  fmt::format("glTF {}: a glTF 1.0 file (asset.version): only glTF 2.0 is supported", name_));
  }

  void document(const json& root) const {
    object(root, "the document");
    version(root);
    child(root, "asset", "", [&](const json& a, const std::string& p) { string(a, "version", p); });
    if (!field(root, "asset")) fail("asset", "is missing");
    index(root, "scene", "");
    strings(root, "extensionsUsed", "");
    strings(root, "extensionsRequired", "");
    const auto none = [](const json&, const std::string&) {};
    objects(root, "accessors", [&](const json& a, const std::string& p) {
      index(a, "bufferView", p);
      index(a, "byteOffset", p);
      index(a, "componentType", p, true);
      boolean(a, "normalized", p);
      index(a, "count", p, true);
      string(a, "type", p);
      numbers(a, "min", p);
      numbers(a, "max", p);
    });
    objects(root, "buffers", [&](const json& b, const std::string& p) {
      string(b, "uri", p);
      index(b, "byteLength", p, true);
    });
    objects(root, "bufferViews", [&](const json& v, const std::string& p) {
      index(v, "buffer", p, true);
      index(v, "byteOffset", p);
      index(v, "byteLength", p, true);
      index(v, "byteStride", p);
      index(v, "target", p);
    });
    objects(root, "images", [&](const json& i, const std::string& p) {
      string(i, "uri", p);
      string(i, "mimeType", p);
      index(i, "bufferView", p);
    });
    objects(root, "materials", [&](const json& m, const std::string& p) { material(m, p); });
    objects(root, "meshes", [&](const json& m, const std::string& p) {
      if (!field(m, "primitives")) fail(at(p, "primitives"), "is missing");
      array(m, "primitives", p, [&](const json& v, const std::string& pp) {
        object(v, pp);
        primitive(v, pp);
      });
      numbers(m, "weights", p);
    });
    objects(root, "nodes", [&](const json& n, const std::string& p) {
      index(n, "camera", p);
      indices(n, "children", p);
      index(n, "skin", p);
      numbers(n, "matrix", p);
      index(n, "mesh", p);
      numbers(n, "rotation", p);
      numbers(n, "scale", p);
      numbers(n, "translation", p);
      numbers(n, "weights", p);
    });
    objects(root, "samplers", [&](const json& s, const std::string& p) {
      for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"}) index(s, key, p);
    });
    objects(root, "scenes", [&](const json& s, const std::string& p) { indices(s, "nodes", p); });
    objects(root, "textures", [&](const json& t, const std::string& p) {
      index(t, "sampler", p);
      index(t, "source", p);
    });
    for (const char* key : {"animations", "cameras", "skins"}) objects(root, key, none);
  }

 private:
  const std::string& name_;
};

// The JSON of a .gltf, or the JSON chunk of a .glb (whose chunk table is checked whole first).
std::string_view json_text(std::span<const uint8_t> bytes, const std::string& name) {
  const std::span<const uint8_t> text = is_glb(bytes) ? glb_chunks(bytes, name).json : bytes;
  return {reinterpret_cast<const char*>(text.data()), text.size()};
}

// Depth of nested arrays and objects, counted over the text without recursion; strings skipped.
void check_depth(std::string_view text, const std::string& name) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw Error(ErrorKind::Corrupt,
                    fmt::format("glTF {}: JSON nested over {} levels deep", name, kMaxJsonDepth));
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

void check_schema(std::span<const uint8_t> bytes, const std::string& name) {
  const std::string_view text = json_text(bytes, name);
  check_depth(text, name);
  const json root = json::parse(text.begin(), text.end(), nullptr, false);
  if (root.is_discarded()) throw Error(ErrorKind::Corrupt, "glTF " + name + ": not valid JSON");
  Checker(name).document(root);
}

}  // namespace lp::gltf
