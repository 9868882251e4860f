#!/usr/bin/env bash
# Renders split over Redis Streams (README's Scale-out), end to end on loopback: a redis-server of its
# own, an api server (--role api) and 1, then 2 workers (--role worker --threads 1); the same render
# (materials preset, SIZE x SIZE, SPP samples per pixel, ITEM samples per item) timed from submission
# to done. Prints samples/s per worker count (over the job's own running time, elapsed_s) and the
# overhead per item: the time the workers spent beyond rendering (waiting for an item, encoding,
# uploading, the coordinator's merge), from the render times the workers log, divided by the items.
#   bench/scale_out.sh [BUILD_DIR] [SIZE] [SPP] [ITEM]      defaults: build 128 512 16
set -euo pipefail
build=${1:-build}
size=${2:-128}
spp=${3:-512}
item=${4:-16}
server="$build/bin/lightprobe-server"
work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

port_of() {  # the port a server printed
  for _ in $(seq 200); do grep -q 'listening on' "$1" && break; sleep 0.05; done
  grep -o 'listening on http://[^ ]*' "$1" | head -1 | sed 's/.*://'
}

redis_port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
redis-server --port "$redis_port" --bind 127.0.0.1 --dir "$work" --appendonly yes --save "" >"$work/redis.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do redis-cli -p "$redis_port" ping >/dev/null 2>&1 && break; sleep 0.05; done
redis="redis://127.0.0.1:$redis_port"
flags=(--port 0 --redis "$redis" --redis-item-spp "$item")

"$server" "${flags[@]}" --role api --state-dir "$work/api" >"$work/api.log" 2>&1 &
pids+=($!)
api="http://127.0.0.1:$(port_of "$work/api.log")/api/v1"
body="{\"envmap\":\"default\",\"scene\":{\"preset\":\"materials\"},\"width\":$size,\"height\":$size,\"spp\":$spp,\"seed\":1}"

run() {  # $1 = workers now running; their logs are $work/worker*.log
  local id start end status
  start=$(date +%s.%N)
  id=$(curl -s -X POST "$api/renders" -H 'Content-Type: application/json' -d "$body" | python3 -c 'import json,sys; print(json.load(sys.stdin)["id"])')
  # The event stream ends with the job (checked every 250 ms): no polling processes on the measured cores.
  curl -sN "$api/renders/$id/events" >"$work/events"
  end=$(date +%s.%N)
  grep '^data:' "$work/events" | tail -1 | sed 's/^data: //' >"$work/status"
  cat "$work"/worker*.log | grep "render $id samples .* done in" | sed 's/.*done in \([0-9.]*\) s/\1/' >"$work/items"
  python3 - "$1" "$start" "$end" "$work/items" "$size" "$spp" "$work/status" <<'PY'
import json, sys
workers, start, end, items, size, spp = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], int(sys.argv[5]), int(sys.argv[6])
status = json.load(open(sys.argv[7]))
times = [float(t) for t in open(items).read().split()]
job = status["elapsed_s"]  # the server's own time from the job's start to its end
overhead = (job * workers - sum(times)) / len(times)
print(f"{workers} worker(s): {status['status']}, job {job:.2f} s ({end - start:.2f} s seen by the client), "
      f"{size*size*spp/job/1e6:.3f} M samples/s, {len(times)} items of {sum(times)/len(times)*1000:.0f} ms "
      f"rendering, overhead {overhead*1000:.1f} ms/item")
PY
}

for n in 1 2; do
  "$server" "${flags[@]}" --role worker --threads 1 --state-dir "$work/w$n" >"$work/worker$n.log" 2>&1 &
  pids+=($!)
  port_of "$work/worker$n.log" >/dev/null
  sleep 1  # the worker reads the active renders
  run "$n"
done
