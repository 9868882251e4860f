#!/usr/bin/env bash
# HTTP load through the real server over loopback, with wrk (installed by scripts/setup): requests/s and
# p50/p99 latency of GET /api/v1/health and POST /api/v1/envmaps/default/samples (count 64, Lua script
# samples_post.lua) at 8, 64 and 256 keep-alive connections, without and then with a render running.
# Usage: bench/http_load.sh [BUILD_DIR] [SECONDS_PER_RUN]; LIGHTPROBE_SERVER=path picks another binary,
# LIGHTPROBE_SERVER_FLAGS adds flags ("--render-priority idle" compares the render priorities).
set -euo pipefail
build=${1:-build}
seconds=${2:-10}
server=${LIGHTPROBE_SERVER:-$build/bin/lightprobe-server}
here="$(cd "$(dirname "$0")" && pwd)"
state=$(mktemp -d)
log=$(mktemp)
# shellcheck disable=SC2086 # the flags are words
"$server" --port 0 --state-dir "$state" ${LIGHTPROBE_SERVER_FLAGS:-} >"$log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null; wait $pid 2>/dev/null; rm -rf "$state" "$log"' EXIT
for _ in $(seq 100); do grep -q 'listening on' "$log" && break; sleep 0.1; done
base="http://127.0.0.1:$(grep -o 'listening on http://[^ ]*' "$log" | sed 's/.*://')"

# One wrk run: prints requests/s, p50, p99 and any errors.
measure() {
  local name=$1 url=$2 connections=$3 render=$4
  shift 4
  local out
  out=$(wrk -t 2 -c "$connections" -d "${seconds}s" --timeout 10s --latency "$@" "$url")
  local rps p50 p99 errors
  rps=$(awk '/^Requests\/sec/ {print $2}' <<<"$out")
  p50=$(awk '$1 == "50%" {print $2}' <<<"$out")
  p99=$(awk '$1 == "99%" {print $2}' <<<"$out")
  errors=$(grep -E 'Socket errors|Non-2xx' <<<"$out" | tr -s ' ' | tr '\n' ';' || true)
  printf '%-8s %-7s %11s %12s %10s %10s  %s\n' "$name" "$render" "$connections" "$rps" "$p50" "$p99" "$errors"
}

all_runs() {
  local render=$1
  for c in 8 64 256; do
    measure health "$base/api/v1/health" "$c" "$render"
    measure samples "$base/api/v1/envmaps/default/samples" "$c" "$render" -s "$here/samples_post.lua"
  done
}

printf '%-8s %-7s %11s %12s %10s %10s\n' endpoint render connections requests/s p50 p99
all_runs no
job=$(curl -s -X POST -H 'Content-Type: application/json' "$base/api/v1/renders" \
  -d '{"envmap": "default", "scene": {"preset": "sphere"}, "width": 512, "height": 512, "spp": 65536}' |
  sed 's/.*"id":"\([^"]*\)".*/\1/')
sleep 1
all_runs yes
curl -s -o /dev/null -X DELETE "$base/api/v1/renders/$job"
