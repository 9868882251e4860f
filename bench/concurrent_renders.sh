#!/usr/bin/env bash
# How running renders share the cores: a server (default flags, or the extra flags given after the
# arguments) takes JOBS identical renders at once (materials preset, SIZE x SIZE, a sample count far
# beyond the measurement); after SECONDS, each job's progress (tiles rendered, times spp) says its share.
# Prints each job's samples per pixel and share, and the ratio of the fastest to the slowest (1.00 is a
# fair share).
#   bench/concurrent_renders.sh [BUILD_DIR] [JOBS] [SIZE] [SECONDS] [server flags...]   defaults: build 2 128 20
set -euo pipefail
build=${1:-build}
jobs=${2:-2}
size=${3:-128}
seconds=${4:-20}
shift $(($# < 4 ? $# : 4))
server="$build/bin/lightprobe-server"
work=$(mktemp -d)
"$server" --port 0 --state-dir "$work/state" --max-running-jobs "$jobs" "$@" >"$work/server.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$work"' EXIT
for _ in $(seq 200); do grep -q 'listening on' "$work/server.log" && break; sleep 0.05; done
api="http://127.0.0.1:$(grep -o 'listening on http://[^ ]*' "$work/server.log" | head -1 | sed 's/.*://')/api/v1"
for _ in $(seq 200); do curl -sf "$api/ready" >/dev/null && break; sleep 0.05; done
body="{\"envmap\":\"default\",\"scene\":{\"preset\":\"materials\"},\"width\":$size,\"height\":$size,\"spp\":65536,\"seed\":1}"
ids=()
for _ in $(seq "$jobs"); do
  ids+=("$(curl -s -X POST "$api/renders" -H 'Content-Type: application/json' -d "$body" |
    python3 -c 'import json,sys; print(json.load(sys.stdin)["id"])')")
done
sleep "$seconds"
for id in "${ids[@]}"; do curl -s "$api/renders/$id"; echo; done | python3 -c '
import json, sys
jobs = [json.loads(line) for line in sys.stdin if line.strip()]
done = [j["progress"] * j["spp"] for j in jobs]
total = sum(done)
for i, d in enumerate(done):
    print(f"job {i}: {d:.0f} spp, {d / total:.2f} of the samples")
print(f"fastest / slowest: {max(done) / max(min(done), 1):.2f}")'
for id in "${ids[@]}"; do curl -s -X DELETE "$api/renders/$id" >/dev/null; done
