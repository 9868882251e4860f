// Partial films of sample ranges: ranges of one render merge into its image (the same per-pixel samples,
// only the order of the sums differs), a range renders the same partial twice, and the bytes a worker
// sends decode to the same partial; broken bytes are refused.
#include <gtest/gtest.h>

#include <atomic>

#include "engine/core/error.hpp"
#include "engine/render/partial_film_codec.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::lighting;
using test::settings;

constexpr int kSize = 24;

std::shared_ptr<const EnvMap> sky_map() {
  return test::make_map(64, [](Vec3 d) { return d.z > 0 ? Rgb{1, 0.8f, 0.6f} : Rgb{0.1f, 0.1f, 0.1f}; });
}

RangePartial render_range(Renderer& renderer, uint32_t first, uint32_t end) {
  std::atomic<bool> cancel{false};
  return *renderer.render_range({first, end}, cancel);
}

// Largest |a - b| / (1e-3 + |a|) over all channels.
double max_relative_difference(const Image& a, const Image& b) {
  double worst = 0;
  for (size_t i = 0; i < a.data().size(); ++i)
    worst = std::max(worst, double(std::abs(a.data()[i] - b.data()[i])) / (1e-3 + std::abs(a.data()[i])));
  return worst;
}

TEST(RenderPartialFilm, RangesMergeIntoTheImageOfOneRender) {
  const auto map = sky_map();
  const SceneDesc scene = *scene_preset("materials");
  std::atomic<bool> cancel{false};
  Renderer whole(scene, lighting(LightingMode::EnvMap), settings(kSize), map);
  whole.render_pass(8, cancel, {});
  Renderer split(scene, lighting(LightingMode::EnvMap), settings(kSize), map);
  // In the other order, as partials arrive from workers.
  RangePartial merged = render_range(split, 4, 8);
  merged.film.merge(render_range(split, 0, 4).film);
  for (size_t p = 0; p < merged.film.pixel_count(); ++p) ASSERT_EQ(merged.film.count(p), 8u);
  EXPECT_LT(max_relative_difference(whole.image(), merged.film.mean()), 1e-5);  // float rounding of sums
  EXPECT_EQ(split.spp_done(), 0);  // ranges leave the renderer's own image alone
}

TEST(RenderPartialFilm, ARangeIsDeterministic) {
  const auto map = sky_map();
  const SceneDesc scene = *scene_preset("sphere");
  Renderer one(scene, lighting(LightingMode::EnvMap), settings(kSize), map);
  Renderer two(scene, lighting(LightingMode::EnvMap), settings(kSize), map);
  const auto a = encode_partial(render_range(one, 3, 7));
  render_range(two, 0, 3);  // what ran before does not matter
  const auto b = encode_partial(render_range(two, 3, 7));
  EXPECT_EQ(a, b);
}

TEST(RenderPartialFilm, CancelledRangeGivesNothing) {
  Renderer renderer(*scene_preset("sphere"), lighting(LightingMode::EnvMap), settings(kSize), sky_map());
  std::atomic<bool> cancel{true};
  EXPECT_FALSE(renderer.render_range({0, 4}, cancel).has_value());
}

TEST(RenderPartialFilm, MeanIsSumOverCount) {
  PartialFilm film(2, 1);
  film.add(0, 0, {3, 6, 9}, 3);
  film.add(0, 0, {1, 2, 3}, 1);
  const Image mean = film.mean();
  EXPECT_FLOAT_EQ(mean.at(0, 0).x, 1.0f);
  EXPECT_FLOAT_EQ(mean.at(0, 0).z, 3.0f);
  EXPECT_EQ(mean.at(1, 0).x, 0.0f);  // no sample yet: black
  EXPECT_THROW(film.merge(PartialFilm(1, 1)), Error);
}

TEST(RenderPartialFilm, FromAMeanHoldsItsSumsAndCounts) {
  Image mean(2, 1);
  mean.set(0, 0, {0.5f, 1.0f, 2.0f});
  mean.set(1, 0, {0.25f, 0.0f, 4.0f});
  const PartialFilm film = PartialFilm::from_mean(mean, 8);
  EXPECT_EQ(film.count(0), 8u);
  EXPECT_EQ(film.count(1), 8u);
  EXPECT_EQ(film.sums()[2], 16.0);
  EXPECT_EQ(film.sums()[3], 2.0);
  EXPECT_EQ(film.mean().at(1, 0).z, 4.0f);
}

TEST(RenderPartialFilm, RangesOutsideCoverWhatIsNotDone) {
  using R = std::vector<SampleRange>;
  EXPECT_EQ(ranges_outside(40, 16, {}), (R{{0, 16}, {16, 32}, {32, 40}}));
  EXPECT_EQ(ranges_outside(64, 16, {{16, 32}}), (R{{0, 16}, {32, 48}, {48, 64}}));
  EXPECT_EQ(ranges_outside(64, 16, {{48, 56}, {0, 8}}), (R{{8, 24}, {24, 40}, {40, 48}, {56, 64}}));
  EXPECT_EQ(ranges_outside(32, 16, {{0, 16}, {16, 32}}), R{});
}

TEST(RenderPartialFilm, CodecRoundTripsAndRefusesBrokenBytes) {
  Renderer renderer(*scene_preset("sphere"), lighting(LightingMode::EnvMap), settings(8), sky_map());
  const RangePartial partial = render_range(renderer, 2, 5);
  const auto bytes = encode_partial(partial);
  EXPECT_EQ(bytes.size(), 36u + 64u * 16u);
  const RangePartial back = decode_partial(bytes, 64);
  EXPECT_EQ(back.range, partial.range);
  EXPECT_EQ(back.rays, partial.rays);
  EXPECT_GT(back.rays, 0u);
  for (size_t p = 0; p < 64; ++p) {
    EXPECT_EQ(back.film.count(p), 3u);
    EXPECT_EQ(back.film.sum(p).y, partial.film.sum(p).y);
  }
  const auto kind = [](std::span<const uint8_t> b, int64_t max_pixels) {
    try {
      decode_partial(b, max_pixels);
    } catch (const Error& e) {
      return e.kind();
    }
    return ErrorKind::InvalidData;
  };
  EXPECT_EQ(kind(bytes, 63), ErrorKind::TooLarge);
  EXPECT_EQ(kind(std::span(bytes).first(bytes.size() - 1), 64), ErrorKind::Corrupt);
  auto bad_count = bytes;
  bad_count[36 + 12] = 4;  // the first pixel claims 4 samples of a 3-sample range
  EXPECT_EQ(kind(bad_count, 64), ErrorKind::Corrupt);
  auto bad_passes = bytes;
  bad_passes[24] = 0x10;  // a pass no renderer has
  EXPECT_EQ(kind(bad_passes, 64), ErrorKind::Corrupt);
  auto empty_range = bytes;
  empty_range[20] = 2;  // end = first
  EXPECT_EQ(kind(empty_range, 64), ErrorKind::Corrupt);
}

}  // namespace
}  // namespace lp::render
