#include "engine/projection/cube_layout.hpp"

#include <algorithm>
#include <array>

#include "engine/projection/cube_face.hpp"

namespace lp {
namespace {

// The cross cell (column, row) of each face, in face order.
constexpr std::array<Pixel, kCubeFaces> kCrossCells = {{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}}};

void copy_face(const Image& from, Pixel from_origin, Image& to, Pixel to_origin, int size) {
  for (int j = 0; j < size; ++j)
    std::copy_n(from.row(from_origin.y + j) + 3 * from_origin.x, 3 * size,
                to.row(to_origin.y + j) + 3 * to_origin.x);
}

}  // namespace

std::optional<FaceTexel> cube_layout_texel(Projection layout, int size, int x, int y) {
  const int i = x % size, j = y % size;
  if (layout == Projection::Cube) return FaceTexel{x / size, i, j};
  for (int face = 0; face < kCubeFaces; ++face)
    if (kCrossCells[size_t(face)].x == x / size && kCrossCells[size_t(face)].y == y / size)
      return FaceTexel{face, i, j};
  return std::nullopt;
}

Pixel cube_layout_pixel(Projection layout, int size, FaceTexel t) {
  if (layout == Projection::Cube) return {t.face * size + t.i, t.j};
  const Pixel cell = kCrossCells[size_t(t.face)];
  return {cell.x * size + t.i, cell.y * size + t.j};
}

Image cube_relayout(const Image& faces, Projection from, Projection to) {
  const int size = *projection_size(from, faces.width(), faces.height());
  const ImageShape shape = projection_shape(to, size);
  Image out(shape.width, shape.height);
  for (int face = 0; face < kCubeFaces; ++face)
    copy_face(faces, cube_layout_pixel(from, size, {face, 0, 0}), out,
              cube_layout_pixel(to, size, {face, 0, 0}), size);
  return out;
}

Image cube_strip_face(const Image& strip, int face) {
  const int size = strip.height();
  Image out(size, size);
  copy_face(strip, {face * size, 0}, out, {0, 0}, size);
  return out;
}

}  // namespace lp
