#pragma once
// OpenEXR's standard attributes on the files we write (exr.cpp adds them): `chromaticities` on every file
// (our pixels are linear Rec.709: sRGB primaries, D65 white), and `envmap` on an environment map laid out as
// OpenEXR defines one (ImfEnvmap.h), so that tools that read it (OpenImageIO's maketx, Nuke) treat it as one.
#include <cstdint>
#include <vector>

#include "engine/image/image_io.hpp"

namespace lp {

// What OpenEXR's `envmap` attribute says of an image: nothing (not an environment map, or one in a
// layout OpenEXR does not define, such as our strip of cube faces), a lat-long map, or OpenEXR's cube
// (its faces one below the other).
enum class ExrEnvmap { None, LatLong, Cube };

// write_exr of an environment map, tagged `envmap`.
std::vector<uint8_t> write_exr_envmap(const Image& image, ExrEnvmap envmap,
                                      ExrCompression compression = ExrCompression::Zip,
                                      PixelPrecision precision = PixelPrecision::Float);
// write_image of an environment map: an EXR tagged `envmap`, any other format as write_image writes it.
std::vector<uint8_t> write_image_envmap(const Image& image, ImageFormat format, const ToneMap& tone,
                                        ExrEnvmap envmap);

}  // namespace lp
