#include "api/brdf_lut_request.hpp"

namespace lp::api {

BrdfLutRequest parse_brdf_lut_query(const Query& q) {
  BrdfLutRequest r;
  r.size = int(query_int(q, "size", kDefaultDfgLutSize, kDfgLutSize.min, kDfgLutSize.max));
  r.multiscatter = query_bool(q, "multiscatter", false);
  r.format = query_enum(q, "format", ImageFormat::Exr);
  return r;
}

Image dfg_lut_image(const DfgLut& lut) {
  Image image(lut.size, lut.size);
  for (int y = 0; y < lut.size; ++y)
    for (int x = 0; x < lut.size; ++x) image.set(x, y, {float(lut.at(x, y).x), float(lut.at(x, y).y), 0.0f});
  return image;
}

}  // namespace lp::api
