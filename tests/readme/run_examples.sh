#!/usr/bin/env bash
# Runs the README's curl block ("Using it with curl") as a user would: against the real server started
# as `make run` starts it (--data-dir tests/data), from a folder where tests/data exists, every curl
# failing on an HTTP error. Then checks what the block promises: the files it wrote are real images, and
# the render it cancelled while running ends `cancelled`.
# Usage: run_examples.sh SERVER_BINARY REPOSITORY_ROOT
set -euo pipefail
server_bin="$1"
root="$(cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'kill "$server_pid" 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$work"' EXIT

"$server_bin" --port 0 --data-dir "$root/tests/data" --state-dir "$work/state" >"$work/server.log" 2>&1 &
server_pid=$!
port=""
for _ in $(seq 100); do
  port="$(sed -nE 's#.*listening on http://127\.0\.0\.1:([0-9]+).*#\1#p' "$work/server.log" | head -1)"
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { cat "$work/server.log"; echo "the server did not start" >&2; exit 1; }

# The block, with the port of this server in place of 8080.
examples="$(awk '/^## Using it with curl/ {on = 1} on && /^```sh$/ {inside = 1; next} inside && /^```$/ {exit} inside' \
  "$root/README.md" | sed "s#^S=http://127.0.0.1:8080/api/v1\$#S=http://127.0.0.1:$port/api/v1#")"
grep -q "127.0.0.1:$port" <<<"$examples" || { echo "no S=http://127.0.0.1:8080/api/v1 line in the block" >&2; exit 1; }

mkdir "$work/user" && ln -s "$root/tests" "$work/user/tests"
cd "$work/user"
cat >examples.sh <<SCRIPT
set -euo pipefail
curl() { command curl -sS --fail-with-body "\$@"; }
$examples
echo
# What the block promised.
for f in map.png marks.png windows.png regions.png render.png; do
  [ "\$(head -c 8 "\$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { echo "\$f is not a PNG" >&2; exit 1; }
done
[ "\$(head -c 4 map.exr | od -An -tx1 | tr -d ' \n')" = 762f3101 ] || { echo "map.exr is not an EXR" >&2; exit 1; }
for f in sheet.jpg thumb.jpg; do
  [ "\$(head -c 3 "\$f" | od -An -tx1 | tr -d ' \n')" = ffd8ff ] || { echo "\$f is not a JPEG" >&2; exit 1; }
done
for f in frame2.webp turntable.webp; do
  [ "\$(tail -c +9 "\$f" | head -c 4)" = WEBP ] || { echo "\$f is not a WebP" >&2; exit 1; }
done
[ "\$(head -c 4 frames.zip | od -An -tx1 | tr -d ' \n')" = 504b0304 ] || { echo "frames.zip is not a zip" >&2; exit 1; }
[ "\$(stat -c %s samples.bin)" = \$((1000000 * 13 * 4)) ] || { echo "samples.bin has the wrong size" >&2; exit 1; }
for _ in \$(seq 300); do
  status="\$(curl \$S/renders/\$big | field status)"
  [ "\$status" = cancelled ] && break
  [ "\$status" = running ] || [ "\$status" = queued ] || { echo "the cancelled render ended \$status" >&2; exit 1; }
  sleep 0.2
done
[ "\$status" = cancelled ] || { echo "the render was not cancelled" >&2; exit 1; }
[ "\$(command curl -s -o /dev/null -w '%{http_code}' \$S/renders/\$id)" = 404 ] || { echo "render \$id was not removed" >&2; exit 1; }
echo "readme examples: all ran"
SCRIPT
bash examples.sh >output.log 2>&1 || { cat output.log; echo "--- server log"; tail -20 "$work/server.log"; exit 1; }
[ -z "${LIGHTPROBE_SHOW_OUTPUT:-}" ] || cat output.log
tail -1 output.log
