#!/usr/bin/env bash
# A turntable end to end on a real server: FRAMES frames of SIZE x SIZE at SPP samples per pixel of a glTF
# model (a path inside DATA_DIR) on forest.exr, from the POST to the job's end; then the time of its
# animated WebP, its contact sheet and its zip of PNG frames.
#   bench/turntable.sh [BUILD_DIR] [FRAMES] [SIZE] [SPP] [DATA_DIR] [MODEL]
#   defaults: build 36 256 16 /usr/share/assimp/models/glTF2 BoxTextured-glTF-Binary/BoxTextured.glb
set -euo pipefail
build=${1:-build}
frames=${2:-36}
size=${3:-256}
spp=${4:-16}
data=${5:-/usr/share/assimp/models/glTF2}
model=${6:-BoxTextured-glTF-Binary/BoxTextured.glb}
here="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
"$build/bin/lightprobe-server" --port 0 --data-dir "$data" --load "forest=$here/tests/data/envmaps/forest.exr" \
  >"$work/server.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$work"' EXIT
for _ in $(seq 200); do grep -q 'listening on' "$work/server.log" && break; sleep 0.05; done
api="http://127.0.0.1:$(grep -o 'listening on http://[^ ]*' "$work/server.log" | head -1 | sed 's/.*://')/api/v1"
for _ in $(seq 200); do curl -sf "$api/ready" >/dev/null && break; sleep 0.05; done
field() { python3 -c "import json,sys; print(json.load(sys.stdin)['$1'])"; }
body="{\"envmap\":\"forest\",\"scene\":{\"objects\":[{\"type\":\"mesh\",\"path\":\"$model\"}]},\"width\":$size,\"height\":$size,\"spp\":$spp,\"turntable\":{\"frames\":$frames,\"elevation_deg\":20,\"elevation_sweep_deg\":10}}"
start=$(date +%s.%N)
id=$(curl -sf -X POST "$api/turntables" -H 'Content-Type: application/json' -d "$body" | field id)
while :; do
  status=$(curl -sf "$api/turntables/$id" | field status)
  [ "$status" = queued ] || [ "$status" = running ] || break
  sleep 0.1
done
end=$(date +%s.%N)
[ "$status" = done ] || { echo "the turntable ended $status" >&2; exit 1; }
echo "turntable: $frames frames of ${size}x$size at $spp spp of $model: $(echo "$end - $start" | bc) s" \
  "($(echo "($end - $start) / $frames" | bc -l | cut -c1-5) s per frame)"
for output in "animation.webp" "contact-sheet?format=jpeg" "frames.zip"; do
  curl -sf -o "$work/out" -w "$output: %{time_total} s, %{size_download} bytes\n" "$api/turntables/$id/$output"
done
