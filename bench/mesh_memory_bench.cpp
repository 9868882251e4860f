// Resident memory a render's mesh takes: peak and held bytes per triangle while an EmbreeScene is built
// from an OBJ (parsing, the model, Embree's BVH), for the bunny and for generated grids of 20k and
// 980k triangles. mesh_memory_bytes() is set from these figures. Run: build/bin/mesh_memory_bench.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bench_data.hpp"
#include "engine/render/embree_scene.hpp"
#include "process_memory.hpp"
#include "support/test_data.hpp"

namespace {

using lp::bench::reset_peak;
using lp::bench::status_bytes;

std::filesystem::path grid_file(int n) {
  const auto path =
      std::filesystem::temp_directory_path() / ("lightprobe-grid-" + std::to_string(n) + ".obj");
  std::ofstream(path) << lp::test::grid_obj(n);
  return path;
}

void measure(benchmark::State& state, const std::filesystem::path& obj) {
  lp::render::SceneDesc scene;
  lp::render::MeshObject mesh;
  mesh.path = obj;
  scene.objects.push_back({mesh, {}});
  const lp::render::MeshLimits limits;
  { lp::render::EmbreeScene warm_up(scene, limits); }  // the first build also starts Embree's threads
  double peak = 0, held = 0, triangles = 0;
  for (auto _ : state) {
    reset_peak();
    const int64_t before = status_bytes("VmRSS");
    lp::render::EmbreeScene built(scene, limits);
    held = double(status_bytes("VmRSS") - before);
    peak = double(status_bytes("VmHWM") - before);
    triangles = double(built.triangle_count());
  }
  state.counters["triangles"] = triangles;
  state.counters["peak_bytes_per_triangle"] = peak / triangles;
  state.counters["held_bytes_per_triangle"] = held / triangles;
  state.counters["estimate_bytes_per_triangle"] = double(lp::render::mesh_memory_bytes(1));
}

void BM_BunnyMemory(benchmark::State& state) {
  const auto bunny = lp::bench::mesh_path("bunny.obj");
  measure(state, bunny);
}
BENCHMARK(BM_BunnyMemory)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_GridMemory(benchmark::State& state) {
  const auto obj = grid_file(int(state.range(0)));
  measure(state, obj);
  std::filesystem::remove(obj);
}
BENCHMARK(BM_GridMemory)->Arg(100)->Arg(700)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
