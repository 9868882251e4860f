#!/usr/bin/env bash
# How much of a render is ray tracing: lightprobe and Blender Cycles render the same scene (a render
# request file of bench/scenes, through bench/cycles_compare.py --scene on Cycles' side) on one thread,
# both on Debian's Embree 3 (one shared library, so a profile tells its share apart). For each renderer:
#   rays      Embree queries, counted by uprobes in a run of their own (rtcIntersect1, rtcOccluded1, and
#             rtcIntersect8 packets counted as 8 rays: lightprobe's camera rays fill whole packets on an
#             image a multiple of 8 wide);
#   seconds   the render at SPP less the render at 1 spp (map, scene and BVH setup): CPU seconds of the
#             whole process (perf's task-clock), without probes, so that other work on a shared machine
#             does not count (wall clock counts the time the render waits for a core);
#   rays/s    rays over those seconds;
#   embree    the share of the render thread's time in libembree3 (perf record, cpu-clock).
# Set them beside render_bench's BM_EmbreeRaw on the same scene for each one's fraction of the ceiling.
# Needs perf (Debian: linux-perf), Blender (blender) and root (uprobes).
# Usage: bench/embree_share.sh [SCENE=bench/scenes/bunny.json] [MAP] [SPP=256] [SIZE=128] [BUILD=build]
set -euo pipefail
trap 'echo "embree_share.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
cd "$(dirname "$0")/.."
# One render: RENDERER SPP, with the settings in the environment (the script runs itself under perf).
if [[ "${1:-}" == --render ]]; then
  if [[ "$2" == lightprobe ]]; then
    exec "$BUILD/bin/lightprobe" render "$SCENE" --envmap "$MAP" --width "$SIZE" --height "$SIZE" --spp "$3" \
      --threads 1 -q -o "$WORK/lightprobe.pfm"
  fi
  exec blender -b --factory-startup --python bench/cycles_compare.py -- --scene "$SCENE" --map "$MAP" \
    --size "$SIZE" --threads 1 --once "$3" --out "$WORK"
fi
export SCENE="${1:-bench/scenes/bunny.json}" MAP="${2:-../shared/data/envmaps/forest.exr}"
[[ -f "$MAP" ]] || MAP="tests/data/envmaps/forest.exr"
export SPP="${3:-256}" SIZE="${4:-128}" BUILD="${5:-build}"
for tool in perf blender; do
  command -v "$tool" > /dev/null || { echo "embree_share.sh: needs $tool" >&2; exit 2; }
done
# awk reads to the end: exiting early could kill ldconfig with SIGPIPE, which pipefail makes an error.
embree="$(ldconfig -p | awk '/libembree3\.so\.3 / && !found {print $NF; found = 1}')"
WORK="$(mktemp -d)" && export WORK
drop_probes() { perf probe -q -d "probe_libembree3:*" 2> /dev/null || true; }
trap 'drop_probes; rm -rf "$WORK"' EXIT
drop_probes  # those a run cut short left behind
for fn in rtcIntersect1 rtcOccluded1 rtcIntersect8; do perf probe -q -x "$embree" --add "$fn"; done

# CPU seconds of one render at SPP, the whole process.
seconds_of() {
  perf stat -x, -e task-clock -o "$WORK/clock" -- "$0" --render "$1" "$2" > /dev/null 2>&1
  awk -F, '/task-clock/ {print $1 / 1000}' "$WORK/clock"
}
# Embree queries of one render at SPP, from the uprobes' counts.
rays_of() {
  perf stat -x, -e 'probe_libembree3:*' -o "$WORK/stat" -- "$0" --render "$1" "$SPP" > /dev/null 2>&1
  awk -F, '/probe_libembree3/ {n = $1 + 0; if ($3 ~ /rtcIntersect8/) n *= 8; sum += n} END {print sum}' \
    "$WORK/stat"
}
# The Embree share of the busiest thread's samples.
share_of() {
  perf record -q -e cpu-clock -F 2000 -o "$WORK/perf.data" -- "$0" --render "$1" "$SPP" > /dev/null 2>&1
  perf report -i "$WORK/perf.data" -s pid,dso --stdio 2> /dev/null | grep -v '^#' | grep . |
    awk '{gsub("%", "", $1); t[$2] += $1; if ($3 ~ /libembree3/) e[$2] += $1}
         END {for (p in t) if (t[p] > best) {best = t[p]; s = e[p] / t[p]} printf "%.3f\n", s}'
}

echo "# $SCENE on $MAP, ${SIZE}x${SIZE}, $SPP spp, 1 thread"
echo "renderer,rays,seconds,rays_per_s,embree_share"
for renderer in lightprobe cycles; do
  rays="$(rays_of "$renderer")"
  full="$(seconds_of "$renderer" "$SPP")" setup="$(seconds_of "$renderer" 1)"
  awk -v r="$renderer" -v n="$rays" -v t="$full" -v s="$setup" -v e="$(share_of "$renderer")" \
    'BEGIN {printf "%s,%d,%.3f,%.0f,%s\n", r, n, t - s, n / (t - s), e}'
done
