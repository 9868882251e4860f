#!/usr/bin/env bash
# Runs every benchmark program of a build and the end-to-end scripts. Usage: bench/run_all.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
here="$(cd "$(dirname "$0")" && pwd)"
for b in "$build"/bin/*_bench; do
  echo "== $(basename "$b")"
  "$b" --benchmark_min_time=0.5
done
echo "== samples endpoint"
bash "$here/samples_endpoint.sh" "$build"
echo "== http load"
bash "$here/http_load.sh" "$build"
