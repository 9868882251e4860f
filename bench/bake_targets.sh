#!/usr/bin/env bash
# Every bake target of one map through the command-line tool: wall and CPU time, peak memory and the
# size of what it writes (the default chain of each target, 1024 GGX samples a texel).
#   bench/bake_targets.sh [BUILD_DIR] [MAP]
#   defaults: build tests/data/envmaps/sunrise.exr
set -euo pipefail
build=${1:-build}
here="$(cd "$(dirname "$0")/.." && pwd)"
map=${2:-$here/tests/data/envmaps/sunrise.exr}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
targets=$("$build/bin/lightprobe" bake --help | sed -nE 's/.*\(one of: ([a-z, ]+)\).*/\1/p' | tr -d ,)
printf '%-9s %8s %8s %8s %8s\n' target wall_s cpu_s peak_MB out_MB
for t in $targets; do
  /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$build/bin/lightprobe" bake "$map" --target "$t" \
    --out "$work/$t" -q
  read -r wall user sys peak <"$work/time"
  size=$(du -sk "$work/$t" | cut -f1)
  printf '%-9s %8.2f %8.2f %8.0f %8.1f\n' "$t" "$wall" "$(echo "$user + $sys" | bc)" "$(echo "$peak / 1024" | bc)" \
    "$(echo "scale=1; $size / 1024" | bc)"
done
