#!/usr/bin/env bash
# Time to a given error, this build against the engine of an earlier commit, measured side by side in one
# run: bench/render_error_bench.cpp (and bench_data) is built against that commit's engine in a temporary
# worktree, then both binaries render each case in turn, the earlier one first. Cases: the materials
# preset on forest.exr, and the glossy scene (bench_data.hpp: diffuse, plastic and rough gold on a plane)
# on city.exr, whose sun carries a fifth of the power; each at 1 and 2 threads. Prints, per case and error
# level, the CPU seconds (all threads) and wall seconds each build takes to reach it, and their ratios.
# Flags after the sixth argument go to both builds' runs (render_error_bench's, e.g. --adaptive=1 or --repeats=3; a build
# whose engine lacks the option ignores it). References are always uniform.
# Usage: bench/speedup_compare.sh BASE_COMMIT [BUILD=build] [size=64] [ref_spp=8192] [max_spp=512] [seeds=4] [flags]
set -euo pipefail
cd "$(dirname "$0")/.."
base_commit="${1:?usage: bench/speedup_compare.sh BASE_COMMIT [BUILD] [size] [ref_spp] [max_spp] [seeds]}"
build="${2:-build}"
size="${3:-64}" ref_spp="${4:-8192}" max_spp="${5:-512}" seeds="${6:-4}"
flags=("${@:7}")
maps="$(pwd)/../shared/data/envmaps"
[[ -f "$maps/city.exr" ]] || maps="$(pwd)/tests/data/envmaps"
new_bin="$build/bin/render_error_bench"
cmake --build "$build" --target render_error_bench > /dev/null

work="$build/speedup_compare"  # in the build tree: a compiler cache finds the earlier builds' objects
rm -rf "$work" && mkdir -p "$work"
trap 'git worktree remove --force "$work/base" 2> /dev/null || true; rm -rf "$work"' EXIT
git worktree add --detach "$work/base" "$base_commit" > /dev/null 2>&1
cp bench/render_error_bench.cpp bench/bench_data.cpp bench/bench_data.hpp "$work/base/bench/"
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$work/base" -B "$work/base/build" -DCMAKE_BUILD_TYPE=Release -DLIGHTPROBE_BUILD_TESTS=OFF \
  -DLIGHTPROBE_BUILD_BENCH=ON "${launcher[@]}" > /dev/null
cmake --build "$work/base/build" -j"$(nproc)" --target render_error_bench > /dev/null
base_bin="$work/base/build/bin/render_error_bench"

# The "relative_rmse,seconds,cpu_seconds,extrapolated" block at the end of a run, as "level cpu wall".
times_to() { sed -n '/^relative_rmse,/,$p' "$1" | tail -n +2 | awk -F, '{print $1, $3, $2, $4}'; }

echo "case,threads,relative_rmse,base_cpu_s,new_cpu_s,cpu_ratio,base_wall_s,new_wall_s,wall_ratio,extrapolated"
for case in "materials forest.exr" "glossy city.exr"; do
  read -r scene map <<< "$case"
  for threads in 1 2; do
    args=("$scene" envmap "$size" "$ref_spp" "$max_spp" "$threads" "--map=$maps/$map" "--seeds=$seeds" "${flags[@]}")
    "$base_bin" "${args[@]}" > "$work/base.txt"
    "$new_bin" "${args[@]}" > "$work/new.txt"
    cat "$work/base.txt" "$work/new.txt" >&2
    paste -d' ' <(times_to "$work/base.txt") <(times_to "$work/new.txt") |
      awk -v c="$scene/$map" -v t="$threads" '{
        printf "%s,%s,%s,%.3f,%.3f,%.2f,%.3f,%.3f,%.2f,%s/%s\n", c, t, $1, $2, $6, $6 / $2, $3, $7, $7 / $3, $4, $8 }'
  done
done
