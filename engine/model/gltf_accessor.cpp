#include "engine/model/gltf_accessor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>

#include "engine/core/error.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

[[noreturn]] void corrupt(const std::string& what, const std::string& problem) {
  throw Error(ErrorKind::Corrupt, what + ": " + problem);
}

const char* component_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_INT:
      return "int";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "float";
    default:
      return "unknown";
  }
}

// The elements of an accessor: where each starts, and how they are laid out.
struct Elements {
  const uint8_t* data = nullptr;
  size_t count = 0, stride = 0;
  int component_type = 0;
  bool normalized = false;
};

Elements elements(const tinygltf::Model& model, int index, int components, std::initializer_list<int> types,
                  const std::string& what) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    corrupt(what, fmt::format("accessor {} does not exist ({} accessors)", index, model.accessors.size()));
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const std::string name = fmt::format("{} (accessor {})", what, index);
  if (a.sparse.isSparse) throw Error(ErrorKind::Unsupported, name + ": sparse accessors are not supported");
  if (std::find(types.begin(), types.end(), a.componentType) == types.end())
    corrupt(name, fmt::format("component type {} ({}) is not allowed here", a.componentType,
                              component_name(a.componentType)));
  const int expected_type = components == 1 ? TINYGLTF_TYPE_SCALAR : components;
  if (a.type != expected_type)
    corrupt(name, fmt::format("has {} components per element, not {}",
                              a.type == TINYGLTF_TYPE_SCALAR ? 1 : a.type, components));
  if (a.bufferView < 0) corrupt(name, "has no buffer view");
  const auto view = buffer_view_bytes(model, a.bufferView, name);
  const size_t element =
      size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) * size_t(components);
  const size_t declared = model.bufferViews[size_t(a.bufferView)].byteStride;
  const size_t stride = declared ? declared : element;
  if (stride < element)
    corrupt(name, fmt::format("byte stride {} is less than an element of {} bytes", stride, element));
  if (a.count == 0) return {view.data(), 0, stride, a.componentType, a.normalized};
  // The last element ends at offset + stride * (count - 1) + element; checked without overflow.
  if (a.byteOffset > view.size() || (a.count - 1) > (view.size() - a.byteOffset) / stride ||
      stride * (a.count - 1) + element > view.size() - a.byteOffset)
    corrupt(name, fmt::format("{} elements from byte offset {} lie outside its buffer view of {} bytes",
                              a.count, a.byteOffset, view.size()));
  return {view.data() + a.byteOffset, a.count, stride, a.componentType, a.normalized};
}

template <class T>
T load(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

float finite_float(const uint8_t* p, const std::string& what, int index) {
  const float v = load<float>(p);
  if (!std::isfinite(v)) corrupt(fmt::format("{} (accessor {})", what, index), "holds a non-finite value");
  return v;
}

// Component c of element i as a float: floats as they are, normalised integers scaled to [0, 1].
float component(const Elements& e, size_t i, int c, const std::string& what, int index) {
  const uint8_t* p = e.data + i * e.stride;
  switch (e.component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return float(p[c]) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return float(load<uint16_t>(p + 2 * c)) / 65535.0f;
    default:
      return finite_float(p + 4 * c, what, index);
  }
}

}  // namespace

std::span<const uint8_t> buffer_view_bytes(const tinygltf::Model& model, int index, const std::string& what) {
  if (index < 0 || size_t(index) >= model.bufferViews.size())
    corrupt(what,
            fmt::format("buffer view {} does not exist ({} buffer views)", index, model.bufferViews.size()));
  const tinygltf::BufferView& v = model.bufferViews[size_t(index)];
  if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size())
    corrupt(what, fmt::format("buffer view {} refers to buffer {}, which does not exist", index, v.buffer));
  const auto& data = model.buffers[size_t(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
    corrupt(what, fmt::format("buffer view {} ({} bytes from offset {}) lies outside buffer {} of {} bytes",
                              index, v.byteLength, v.byteOffset, v.buffer, data.size()));
  return {data.data() + v.byteOffset, v.byteLength};
}

size_t accessor_count(const tinygltf::Model& model, int index, const std::string& what) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    corrupt(what, fmt::format("accessor {} does not exist ({} accessors)", index, model.accessors.size()));
  return model.accessors[size_t(index)].count;
}

std::vector<Vec3> read_vec3(const tinygltf::Model& model, int index, const std::string& what) {
  const Elements e = elements(model, index, 3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, what);
  std::vector<Vec3> out(e.count);
  for (size_t i = 0; i < e.count; ++i)
    out[i] = {component(e, i, 0, what, index), component(e, i, 1, what, index),
              component(e, i, 2, what, index)};
  return out;
}

std::vector<std::array<float, 4>> read_vec4(const tinygltf::Model& model, int index,
                                            const std::string& what) {
  const Elements e = elements(model, index, 4, {TINYGLTF_COMPONENT_TYPE_FLOAT}, what);
  std::vector<std::array<float, 4>> out(e.count);
  for (size_t i = 0; i < e.count; ++i)
    for (int c = 0; c < 4; ++c) out[i][size_t(c)] = component(e, i, c, what, index);
  return out;
}

namespace {

// Float, or normalised unsigned byte or short elements of `components` components.
Elements unit_elements(const tinygltf::Model& model, int index, int components, const std::string& what) {
  const Elements e = elements(model, index, components,
                              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                              what);
  if (e.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !e.normalized)
    corrupt(fmt::format("{} (accessor {})", what, index), "integer components must be normalized");
  return e;
}

}  // namespace

std::vector<std::array<float, 4>> read_color(const tinygltf::Model& model, int index,
                                             const std::string& what) {
  accessor_count(model, index, what);  // checks that it exists
  const int components = model.accessors[size_t(index)].type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  const Elements e = unit_elements(model, index, components, what);
  std::vector<std::array<float, 4>> out(e.count, {1, 1, 1, 1});
  for (size_t i = 0; i < e.count; ++i)
    for (int c = 0; c < components; ++c) out[i][size_t(c)] = component(e, i, c, what, index);
  return out;
}

std::vector<Point2> read_uv(const tinygltf::Model& model, int index, const std::string& what) {
  const Elements e = unit_elements(model, index, 2, what);
  std::vector<Point2> out(e.count);
  for (size_t i = 0; i < e.count; ++i)
    out[i] = {component(e, i, 0, what, index), component(e, i, 1, what, index)};
  return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& what) {
  const Elements e = elements(model, index, 1,
                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                              what);
  std::vector<uint32_t> out(e.count);
  for (size_t i = 0; i < e.count; ++i) {
    const uint8_t* p = e.data + i * e.stride;
    out[i] = e.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? p[0]
             : e.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p)
                                                                          : load<uint32_t>(p);
  }
  return out;
}

}  // namespace lp::gltf
