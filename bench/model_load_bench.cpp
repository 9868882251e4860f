// Loading models and building texture mip pyramids: BoxTextured (.gltf with an external 211 x 211 PNG,
// and .glb), 2CylinderEngine (.glb, 121k triangles, no textures: tangent generation) from Debian's
// assimp-testmodels, the test quad's OBJ/MTL; mip pyramids of RGB and RGBA textures of power-of-two and
// other sizes; trilinear lookups. Run: build/bin/model_load_bench.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/core/rng.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace {

const std::filesystem::path kSamples = lp::test::assimp_model_path("glTF2");

void load(benchmark::State& state, const std::filesystem::path& path) {
  size_t triangles = 0;
  for (auto _ : state) {
    const lp::Model m = lp::load_model(path, {});
    triangles = m.triangle_count();
    benchmark::DoNotOptimize(m.positions.data());
  }
  state.counters["triangles"] = double(triangles);
  state.counters["triangles/s"] =
      benchmark::Counter(double(triangles), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK_CAPTURE(load, box_textured_gltf, kSamples / "BoxTextured-glTF/BoxTextured.gltf")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load, box_textured_glb, kSamples / "BoxTextured-glTF-Binary/BoxTextured.glb")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load, cylinder_engine_glb, kSamples / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load, quad_obj_mtl, lp::test::model_path("obj/quad.obj"))->Unit(benchmark::kMillisecond);

std::vector<float> noise(int w, int h, int channels) {
  lp::Rng rng(7, 0);
  std::vector<float> t(size_t(w) * size_t(h) * size_t(channels));
  for (float& v : t) v = rng.uniform_float();
  return t;
}

// Constructing a Texture builds its whole pyramid; the texel copy is outside the timing.
void mip_pyramid(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1)), channels = int(state.range(2));
  const auto texels = noise(w, h, channels);
  for (auto _ : state) {
    state.PauseTiming();
    auto copy = texels;
    state.ResumeTiming();
    const lp::Texture t(w, h, channels, std::move(copy));
    benchmark::DoNotOptimize(t.level_count());
  }
  state.counters["texels/s"] =
      benchmark::Counter(double(w) * h, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(mip_pyramid)
    ->Args({1024, 1024, 3})
    ->Args({1024, 1024, 4})
    ->Args({1000, 1000, 3})
    ->Args({2048, 2048, 3})
    ->Args({4096, 4096, 3})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void trilinear_lookup(benchmark::State& state) {
  const lp::Texture t(1024, 1024, 3, noise(1024, 1024, 3));
  lp::Rng rng(3, 0);
  float sum = 0;
  for (auto _ : state) {
    const lp::Point2 uv{rng.uniform_float() * 4 - 2, rng.uniform_float()};
    sum += t.sample(uv, rng.uniform_float() * 10, {lp::WrapMode::MirroredRepeat, lp::WrapMode::Repeat}).r;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(trilinear_lookup);

}  // namespace

BENCHMARK_MAIN();
