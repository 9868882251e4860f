// A render's record in the state directory: it reads back as written, the sample ranges of a render
// split over Redis among it, and a record whose ranges overlap or do not hold its samples is refused.
#include "server/renders/render_record.hpp"

#include <gtest/gtest.h>

namespace lp::server {
namespace {

RenderRecord split_record() {
  RenderRecord r;
  r.id = "3f9c0a7d12e4b856";
  r.request = {{"envmap", "default"}};
  r.status = JobStatus::Interrupted;
  r.spp_done = 24;
  r.ranges_done = {{16, 32}, {0, 8}};
  r.image_file = "3f9c0a7d12e4b856.24.exr";
  r.envmap_fingerprint = "ab-4x2";
  r.model_hashes = {{0, "c0ffee"}, {12, ""}};
  return r;
}

TEST(RenderRecord, ReadsBackWithTheRangesDone) {
  const RenderRecord back = parse_render_record(record_json(split_record()));
  EXPECT_EQ(back.spp_done, 24);
  ASSERT_EQ(back.ranges_done.size(), 2u);
  EXPECT_EQ(back.ranges_done[0], (render::SampleRange{0, 8}));
  EXPECT_EQ(back.ranges_done[1], (render::SampleRange{16, 32}));
  EXPECT_EQ(back.image_file, "3f9c0a7d12e4b856.24.exr");
}

TEST(RenderRecord, ReadsBackTheHashesOfItsModels) {
  const auto json = record_json(split_record());
  EXPECT_EQ(json["model_hashes"], nlohmann::json({{"0", "c0ffee"}, {"12", ""}}));
  EXPECT_EQ(parse_render_record(json).model_hashes, (ModelHashes{{0, "c0ffee"}, {12, ""}}));
  auto without = json;
  without.erase("model_hashes");  // a record of an earlier version
  EXPECT_TRUE(parse_render_record(without).model_hashes.empty());
  for (const char* key : {"x", "-1", "1x", ""}) {
    auto bad = json;
    bad["model_hashes"] = {{key, "c0ffee"}};
    EXPECT_THROW(parse_render_record(bad), std::invalid_argument) << key;
  }
}

TEST(RenderRecord, ReadsBackItsDenoisedImage) {
  RenderRecord r = split_record();
  EXPECT_FALSE(parse_render_record(record_json(r)).denoise_s);
  r.denoise_s = 1.25;
  auto json = record_json(r);
  EXPECT_EQ(parse_render_record(json).denoise_s, 1.25);
  json.erase("denoise_s");  // a record of an earlier version
  EXPECT_FALSE(parse_render_record(json).denoise_s);
  r.spp_done = 0;
  r.ranges_done.clear();
  r.image_file.clear();
  EXPECT_THROW(parse_render_record(record_json(r)), std::invalid_argument);  // denoised, without an image
}

TEST(RenderRecord, ARecordWithoutRangesIsTheFirstSamples) {
  auto json = record_json(split_record());
  json.erase("sample_ranges_done");
  EXPECT_TRUE(parse_render_record(json).ranges_done.empty());
}

TEST(RenderRecord, RangesThatOverlapOrMissSamplesAreRefused) {
  auto overlapping = record_json(split_record());
  overlapping["sample_ranges_done"] = {{0, 16}, {8, 16}};
  EXPECT_THROW(parse_render_record(overlapping), std::invalid_argument);
  auto short_of_samples = record_json(split_record());
  short_of_samples["sample_ranges_done"] = {{0, 8}};
  EXPECT_THROW(parse_render_record(short_of_samples), std::invalid_argument);
  auto empty_range = record_json(split_record());
  empty_range["sample_ranges_done"] = {{8, 8}, {0, 24}};
  EXPECT_THROW(parse_render_record(empty_range), std::invalid_argument);
  auto not_pairs = record_json(split_record());
  not_pairs["sample_ranges_done"] = {"0-24"};
  EXPECT_THROW(parse_render_record(not_pairs), std::exception);
}

}  // namespace
}  // namespace lp::server
