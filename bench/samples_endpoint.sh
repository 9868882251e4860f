#!/usr/bin/env bash
# End to end: POST /envmaps/{id}/samples with N = 1e6 in binary, through the real server over
# loopback, timed by curl (total time from connect to the last byte). Usage: bench/samples_endpoint.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
data="$(cd "$(dirname "$0")/.." && pwd)/../shared/data/envmaps"
log=$(mktemp)
"$build/bin/lightprobe-server" --port 0 --load "forest=$data/forest.exr" >"$log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null; rm -f "$log"' EXIT
for _ in $(seq 100); do grep -q 'listening on' "$log" && break; sleep 0.1; done
port=$(grep -o 'listening on http://[^ ]*' "$log" | sed 's/.*://')
url="http://127.0.0.1:$port/api/v1/envmaps/forest/samples"
for strategy in independent stratified sobol; do
  for run in 1 2 3; do
    curl -s -o /dev/null -w "$strategy binary N=1e6: %{time_total} s, %{size_download} bytes\n" \
      -H 'Accept: application/octet-stream' -H 'Content-Type: application/json' -X POST "$url" -d "{\"count\":1000000,\"seed\":$run,\"strategy\":\"$strategy\"}"
  done
done
curl -s -o /dev/null -w "independent json N=1e6: %{time_total} s, %{size_download} bytes\n" \
  -H 'Content-Type: application/json' -X POST "$url" -d '{"count":1000000,"seed":1}'
