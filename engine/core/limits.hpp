#pragma once
// The ranges and limits the engine owns. Engine parameter structs validate against them; the API's
// parsers, messages, server flags and api/openapi.yaml take them from here.
#include <fmt/format.h>

#include <cstdint>
#include <string>

namespace lp {

// A closed interval [min, max]; NaN is in no range.
template <class T>
struct Range {
  T min, max;
  constexpr bool contains(T v) const { return v >= min && v <= max; }
};

// "must be in [a, b]", the one wording of a range in every error message.
template <class T>
std::string range_message(const Range<T>& r) {
  return fmt::format("must be in [{}, {}]", r.min, r.max);
}

namespace limits {

// Materials. The index of refraction covers every transparent material renders use (water 1.33,
// glass 1.5, diamond 2.42) up to silicon and germanium (about 4); above it the dielectric sampling
// keeps almost nothing but total internal reflection.
inline constexpr Range<double> kIor{1.0, 4.0};
inline constexpr Range<double> kReflectance{0.0, 1.0};  // albedo and colour channels
inline constexpr Range<double> kRoughness{0.0, 1.0};    // GGX alpha
inline constexpr Range<double> kConductorEta{0.001, 20.0};
inline constexpr Range<double> kConductorK{0.0, 20.0};

// Scenes: positions, sizes and angles.
inline constexpr Range<double> kCoordinate{-1e6, 1e6};
inline constexpr Range<double> kSize{1e-6, 1e6};  // sphere radius, mesh scale
inline constexpr Range<double> kRotationDeg{-360.0, 360.0};
inline constexpr Range<double> kFovDeg{1.0, 179.0};         // vertical field of view
inline constexpr Range<double> kElevationDeg{-89.0, 89.0};  // a framed camera's, off the poles: +z stays up
inline constexpr Range<double> kFitMargin{0.1, 100.0};      // a framed object's radius over the view's
inline constexpr Range<int64_t> kTurntableFrames{1, 720};   // frames of one turntable

// Lighting.
inline constexpr Range<double> kIntensity{0.0, 1e6};
// The widest importance grid a render samples on: 2048 x 1024 cells (2 M; 74 MiB with their radiance
// and sampling tables) resolve a sun as well as any map needs, where an 8K map's own grid would take
// 32 M cells and 1.2 GiB.
inline constexpr int kDefaultImportanceMaxWidth = 2048;

// Render settings: bounces of a path; a request's limit (--max-render-depth) lies inside.
inline constexpr Range<int64_t> kMaxDepth{0, 1024};

// Images read from files. The default largest map is an 8K lat-long map (8192 x 4096).
inline constexpr int64_t kDefaultMaxImagePixels = int64_t{8192} * 4096;
inline constexpr int kMaxImageDimension = 65536;

// Mesh files.
inline constexpr int64_t kDefaultMaxMeshTriangles = 2'000'000;
inline constexpr int64_t kMaxMeshFileBytes = int64_t{256} << 20;

// Model textures: pixels of one texture's base level, and of all the textures of one model together
// (a 4096 x 4096 texture takes 268 MB as float RGB with its mip levels).
inline constexpr int64_t kDefaultMaxTexturePixels = int64_t{4096} * 4096;
inline constexpr int64_t kDefaultMaxModelTexturePixels = 2 * kDefaultMaxTexturePixels;

// Fresnel tables: indices of refraction of any medium (the real part of a conductor's too) and the
// extinction coefficient k span [0.001, 1000] and [0, 1000], far beyond the materials a render uses;
// the angle step is in degrees.
inline constexpr Range<double> kFresnelIndex{0.001, 1000.0};
inline constexpr Range<double> kFresnelExtinction{0.0, 1000.0};
inline constexpr Range<double> kFresnelStepDeg{0.01, 90.0};

// Spherical harmonics: bands 1 to 5 (25 coefficients; the irradiance of band 5 is already below 1% of
// band 1's, and higher bands ring).
inline constexpr Range<int> kShBands{1, 5};

// Prefiltered specular chains (engine/prefilter): the width of level 0 in texels (a lat-long level is
// twice as wide as high), the number of levels (each half the previous: at most log2 of the base width
// so that the last is at least 2 x 1, or a cube's full pyramid down to 1 x 1 faces, one more) and the
// GGX samples per texel. A 2048-wide chain of 16384
// samples is minutes of work on a few cores, the most a job should hold a runner for.
inline constexpr Range<int> kPrefilterBaseSize{8, 2048};
inline constexpr Range<int> kPrefilterLevels{1, 12};
inline constexpr Range<int> kPrefilterSamples{16, 16384};
// Sun extraction (engine/sun/sun_params.hpp says what each is).
inline constexpr Range<double> kSunThreshold{0.001, 1.0};
inline constexpr Range<double> kSunMaxRadiusDeg{0.05, 30.0};
inline constexpr Range<double> kSunMinShare{0.0, 1.0};
inline constexpr Range<double> kSunMinContrast{1.0, 1e6};
// Projections of a map (engine/projection): the face size of a cube or cross, the side of an octahedral or
// equal-area square. The answer's pixels are bounded by the largest map (--max-pixels) too.
inline constexpr Range<int64_t> kProjectionSize{2, 8192};

}  // namespace limits
}  // namespace lp
