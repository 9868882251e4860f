// The projection query parameters: defaults from the map's width, sizes bounded by the largest image,
// the parameters refused where they do not apply, and upload shapes checked against their projection.
#include "api/projection_params.hpp"

#include <gtest/gtest.h>

#include "api/api_error.hpp"
#include "api/parameters.hpp"

namespace lp::api {
namespace {

std::string refusal(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const ApiError& e) {
    return std::string(code_name(e.code())) + ": " + e.what();
  }
  return "accepted";
}

TEST(ProjectionParams, DefaultsAreTheMapAsHeld) {
  const ProjectionParams p = parse_projection_params({});
  EXPECT_EQ(p.projection, Projection::LatLong);
  EXPECT_FALSE(p.size);
  EXPECT_FALSE(p.face);
  const ProjectionParams cube =
      parse_projection_params({{"projection", "cube"}, {"face", "nz"}, {"size", "32"}});
  EXPECT_EQ(cube.projection, Projection::Cube);
  EXPECT_EQ(cube.face, CubeFace::NegZ);
  EXPECT_EQ(cube.size, 32);
}

TEST(ProjectionParams, TheDefaultSizeFollowsTheMapsWidthWithinTheLargestImage) {
  const auto params = [](Projection projection, std::optional<int> size = {}) {
    ProjectionParams p;
    p.projection = projection;
    p.size = size;
    return p;
  };
  const int64_t max = kMaxPixels.fallback;  // 8192 x 4096
  EXPECT_EQ(projection_image_size(params(Projection::Cube), 1024, max), 256);
  EXPECT_EQ(projection_image_size(params(Projection::Cross), 1024, max), 256);
  EXPECT_EQ(projection_image_size(params(Projection::Octahedral), 1024, max), 512);
  EXPECT_EQ(projection_image_size(params(Projection::EqualArea), 8192, max), 4096);
  EXPECT_EQ(projection_image_size(params(Projection::Cube), 8192, max), 2048);   // 6 x 2048^2 fit
  EXPECT_EQ(projection_image_size(params(Projection::Cross), 8192, max), 1672);  // 12 x 1672^2 <= 8192 x 4096
  EXPECT_EQ(projection_image_size(params(Projection::Cube), 4, max), 2);         // the least size
  EXPECT_EQ(projection_image_size(params(Projection::EqualArea, 77), 1024, max), 77);
  EXPECT_EQ(
      refusal([&] { projection_image_size(params(Projection::Cube, 4096), 1024, max); }),
      "invalid_field: field 'size': a cube of size 4096 has 100663296 pixels, over the largest image of "
      "33554432 (--max-pixels)");
}

TEST(ProjectionParams, ParametersWhereTheyDoNotApplyAreRefused) {
  EXPECT_EQ(refusal([] {
              parse_projection_params({{"size", "64"}});
            }),
            "invalid_field: field 'size': applies to the projections cube, cross, octahedral and equal-area; "
            "latlong is the map as it is held");
  EXPECT_EQ(refusal([] {
              parse_projection_params({{"projection", "octahedral"}, {"face", "px"}});
            }),
            "invalid_field: field 'face': applies to projection=cube only");
  EXPECT_EQ(refusal([] {
              parse_projection_params({{"projection", "cube"}, {"size", "8193"}});
            }),
            "invalid_field: field 'size': must be in [2, 8192], got 8193");
  EXPECT_EQ(refusal([] {
              parse_projection_params({{"projection", "fisheye"}});
            }),
            "invalid_field: field 'projection': 'fisheye' is not one of: latlong, cube, cross, octahedral, "
            "equal-area");
}

TEST(ProjectionParams, AnUploadsShapeMustFitItsProjection) {
  const int64_t max = kMaxPixels.fallback;
  EXPECT_EQ(input_latlong_width(Projection::Cross, 400, 300, max), 400);
  EXPECT_EQ(input_latlong_width(Projection::Cube, 600, 100, max), 400);
  EXPECT_EQ(input_latlong_width(Projection::EqualArea, 300, 300, max), 600);
  EXPECT_EQ(
      refusal([&] { input_latlong_width(Projection::Cross, 400, 200, max); }),
      "invalid_field: field 'projection': the image must be 4:3 (4N x 3N pixels) for projection cross, got "
      "400 x 200");
  EXPECT_EQ(refusal([&] { input_latlong_width(Projection::Octahedral, 30, 31, max, "input_projection"); }),
            "invalid_field: field 'input_projection': the image must be square (N x N pixels) for projection "
            "octahedral, got 30 x 31");
  // A 4096 x 4096 square becomes 8192 x 4096, the largest map; one pixel wider does not fit.
  EXPECT_EQ(input_latlong_width(Projection::EqualArea, 4096, 4096, max), 8192);
  EXPECT_EQ(refusal([&] { input_latlong_width(Projection::EqualArea, 4097, 4097, max); }),
            "too_large: converted from equal-area, the lat-long map would have 8194 x 4097 pixels, over the "
            "largest map of 33554432 (--max-pixels)");
  EXPECT_EQ(parse_input_projection({{"projection", "equal-area"}}), Projection::EqualArea);
  EXPECT_EQ(parse_input_projection({}), Projection::LatLong);
}

}  // namespace
}  // namespace lp::api
