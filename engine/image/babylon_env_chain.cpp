#include "engine/image/babylon_env_chain.hpp"

#include <bit>

#include "engine/core/error.hpp"
#include "engine/image/babylon_env.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/rgbd.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"

namespace lp {

namespace {

// Half the size, each texel the mean of the four it covers (the texels of a face share a solid angle to
// within the few percent a 2x2 box ignores).
Image box_half(const Image& face) {
  const int size = face.width() / 2;
  Image out(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      out.set(x, y,
              (face.at(2 * x, 2 * y) + face.at(2 * x + 1, 2 * y) + face.at(2 * x, 2 * y + 1) +
               face.at(2 * x + 1, 2 * y + 1)) *
                  0.25f);
  return out;
}

std::vector<uint8_t> encode_face(const Image& face) {
  return encode_png_rgba8(encode_rgbd_pixels(face), face.width(), face.height());
}

}  // namespace

Image babylon_face(const Image& strip, int face) {
  const int ours = face == int(CubeFace::PosX)   ? int(CubeFace::NegX)
                   : face == int(CubeFace::NegX) ? int(CubeFace::PosX)
                                                 : face;
  const Image source = cube_strip_face(strip, ours);
  const int size = source.width();
  Image out(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) out.set(x, y, source.at(size - 1 - x, size - 1 - y));
  return out;
}

std::vector<uint8_t> babylon_env_file(const PrefilteredChain& chain, const ShCoefficients& radiance) {
  const PrefilterParams& p = chain.params;
  if (p.projection != Projection::Cube)
    throw Error(ErrorKind::InvalidArgument, "projection", "must be cube for a Babylon .env");
  if (!std::has_single_bit(unsigned(p.base_size)))
    throw Error(ErrorKind::InvalidArgument, "base_size", "must be a power of two for a Babylon .env");
  BabylonEnv env;
  env.width = p.base_size;
  env.irradiance = babylon_polynomial(radiance, kWorldToBabylon);
  std::vector<Image> faces(kCubeFaces);
  for (int level = 0; level < babylon_env_levels(env.width); ++level)
    for (int f = 0; f < kCubeFaces; ++f) {
      Image& face = faces[size_t(f)];
      face = level < int(chain.levels.size()) ? babylon_face(chain.levels[size_t(level)], f) : box_half(face);
      env.specular.push_back(encode_face(face));
    }
  return write_babylon_env(env);
}

}  // namespace lp
