// The passes of a progressive render: their sizes, and an adaptive render's uniform warm-up.
#include <gtest/gtest.h>

#include <numeric>

#include "engine/render/adaptive_allocation.hpp"
#include "engine/render/pass_schedule.hpp"

namespace lp::render {
namespace {

int total(const std::vector<RenderPass>& passes) {
  return std::accumulate(passes.begin(), passes.end(), 0,
                         [](int sum, const RenderPass& p) { return sum + p.spp; });
}

TEST(PassSchedule, DoublesFromOneUpToTheCapAndSumsToTheSpp) {
  EXPECT_EQ(pass_schedule(1), (std::vector<int>{1}));
  EXPECT_EQ(pass_schedule(10), (std::vector<int>{1, 1, 2, 4, 2}));
  EXPECT_EQ(pass_schedule(100, 32), (std::vector<int>{1, 1, 2, 4, 8, 16, 32, 32, 4}));
}

TEST(PassSchedule, AUniformRenderHasOnlyUniformPasses) {
  RenderSettings s;
  s.spp = 300;
  const auto passes = render_passes(s);
  EXPECT_EQ(total(passes), 300);
  for (const RenderPass& p : passes) EXPECT_FALSE(p.adaptive);
}

TEST(PassSchedule, AnAdaptiveRenderWarmsUpUniformlyThenAdapts) {
  RenderSettings s;
  s.sampling = SamplingMode::Adaptive;
  for (const int spp : {1, 2, 3, 8, 64, 1000}) {
    SCOPED_TRACE(spp);
    s.spp = spp;
    const auto passes = render_passes(s);
    EXPECT_EQ(total(passes), spp);
    int uniform = 0;
    size_t i = 0;
    for (; i < passes.size() && !passes[i].adaptive; ++i) uniform += passes[i].spp;
    for (; i < passes.size(); ++i) EXPECT_TRUE(passes[i].adaptive) << "a uniform pass after an adaptive one";
    EXPECT_EQ(uniform, adaptive_warmup_spp(spp));
    EXPECT_GE(uniform, std::min(spp, 2));  // the deviations need 2 samples a pixel
  }
}

}  // namespace
}  // namespace lp::render
