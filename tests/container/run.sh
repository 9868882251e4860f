#!/usr/bin/env bash
# The container image, built and tested from inside: podman builds docker/Dockerfile (after the local
# base images, tests/container/base_image.sh), the image's configuration is checked (non-root user,
# port, volumes, health check, labels, no compiler, no apt lists), then its entrypoint serves on a free
# port given as LIGHTPROBE_PORT with tests/data/envmaps mounted read-only at /data and a fresh directory
# at /state, and the API smoke test (smoke.py) runs against it, as does the image's own HEALTHCHECK
# command, unchanged. SIGTERM stops it.
# As ../shared/docs/container-testing.md describes for machines without a Docker engine: build with
# --isolation chroot, run with `buildah run --isolation chroot` (the host's network: the server's port
# is on 127.0.0.1 here). Exits 77, which ctest counts as skipped, without podman, buildah, python3 or root.
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
here="$root/tests/container"
image="${LIGHTPROBE_TEST_IMAGE:-localhost/lightprobe:test}"

skip() {
  echo "container test skipped: $*"
  exit 77
}
for tool in podman buildah python3; do
  command -v "$tool" >/dev/null 2>&1 || skip "no $tool (apt-get install podman buildah debootstrap python3)"
done
[ "$(id -u)" = 0 ] || skip "podman and buildah with chroot isolation need root here"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

bash "$here/base_image.sh"

echo "== podman build (docker/Dockerfile)"
# Without intermediate images (--layers=false) each build leaves only the image, and the one it replaces
# is removed: nothing piles up. The compiler cache (a build cache mount) makes a rebuild about a minute.
previous="$(podman image inspect --format '{{.Id}}' "$image" 2>/dev/null || true)"
started=$SECONDS
revision="$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)"
nice podman build --isolation chroot --format docker --layers=false -f "$root/docker/Dockerfile" -t "$image" \
  --build-arg REVISION="$revision" --build-arg CREATED="$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$root"
echo "image built in $((SECONDS - started)) s"
if [ -n "$previous" ] && [ "$previous" != "$(podman image inspect --format '{{.Id}}' "$image")" ]; then
  podman rmi "$previous" >/dev/null || true
fi
podman images "$image"

echo "== image configuration"
config() { podman image inspect --format "{{json $1}}" "$image"; }
[ "$(config .Config.ExposedPorts)" = '{"8080/tcp":{}}' ] || fail "EXPOSE: $(config .Config.ExposedPorts)"
[ "$(config .Config.Volumes)" = '{"/data":{},"/state":{}}' ] || fail "VOLUME: $(config .Config.Volumes)"
[ "$(config .Config.User)" = '"lightprobe"' ] || fail "USER: $(config .Config.User)"
# The entrypoint and the health check command, as argument lists (one per line).
json_lines() { python3 -c 'import json, sys; print("\n".join(json.load(sys.stdin)))'; }
mapfile -t entrypoint < <(config .Config.Entrypoint | json_lines)
mapfile -t healthcheck < <(config .Config.Healthcheck.Test | json_lines)
[ "${healthcheck[0]:-}" = CMD ] || fail "HEALTHCHECK: $(config .Config.Healthcheck)"
echo "entrypoint: ${entrypoint[*]}"
echo "healthcheck: ${healthcheck[*]:1}"

work="$(mktemp -d /tmp/lightprobe-container-XXXXXX)"
container=""
server=""
cleanup() {
  if [ -n "$server" ]; then  # buildah run stops what it runs when it gets SIGTERM (not SIGKILL)
    kill -TERM "$server" 2>/dev/null || true
    wait "$server" || true
  fi
  if [ -n "$container" ]; then buildah rm "$container" >/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
container="$(buildah from "$image")"
# buildah 1.28 puts its own anonymous volumes over the image's VOLUME paths when -v names more than one
# of them; without the declarations in this working container (the image keeps them) -v mounts as asked.
buildah config --volume /data- --volume /state- "$container"
inside() { buildah run --isolation chroot "$container" -- "$@"; }

uid="$(inside id -u)"
[ "$uid" != 0 ] || fail "the image runs as root"
inside sh -c '! command -v cc c++ g++ gcc cmake' >/dev/null || fail "a compiler in the runtime image"
lists="$(buildah run --isolation chroot --user root "$container" -- find /var/lib/apt/lists /var/cache/apt -type f ! -name lock)"
[ -z "$lists" ] || fail "apt lists or caches left in the image: $lists"
inside /usr/local/bin/lightprobe-server --version
echo "runs as uid $uid; no compiler, apt lists or caches"
# The command-line tool beside the server, on a map of the data volume.
buildah run --isolation chroot -v "$root/tests/data/envmaps:/data:ro" "$container" \
  -- lightprobe info /data/forest.exr | grep -q '"width": *256' || fail "lightprobe info in the image"

label() { podman image inspect --format "{{index .Config.Labels \"org.opencontainers.image.$1\"}}" "$image"; }
version="$(sed -n 's/^set(LIGHTPROBE_VERSION \([^)]*\))/\1/p' "$root/cmake/version.cmake")"
[ "$(label version)" = "$version" ] || fail "label version '$(label version)', the project's is $version"
[ "$(label revision)" = "$revision" ] || fail "label revision '$(label revision)', built from $revision"
[ -n "$(label title)" ] && [ -n "$(label created)" ] || fail "OCI labels: $(config .Config.Labels)"
echo "labels: version $version, revision $revision"

echo "== the server in the image, on a port set as docker run -e sets it"
# The host's network (chroot isolation): a free port of the host, given as LIGHTPROBE_PORT.
port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
buildah config --env LIGHTPROBE_PORT="$port" "$container"
mkdir "$work/state"
chown "$uid" "$work/state"
buildah run --isolation chroot -v "$root/tests/data/envmaps:/data:ro" -v "$work/state:/state" "$container" \
  -- "${entrypoint[@]}" >"$work/server.log" 2>&1 &
server=$!
for _ in $(seq 600); do
  grep -q "listening on http://0\.0\.0\.0:$port" "$work/server.log" && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
grep -q "listening on http://0\.0\.0\.0:$port" "$work/server.log" ||
  { cat "$work/server.log"; fail "the server did not listen on 0.0.0.0:$port (LIGHTPROBE_PORT)"; }
echo "listening on 0.0.0.0:$port"

# The image's own health check command, unchanged: it finds the port in LIGHTPROBE_PORT too.
for _ in $(seq 100); do
  inside "${healthcheck[@]:1}" >/dev/null 2>&1 && break
  sleep 0.1
done
inside "${healthcheck[@]:1}" || { cat "$work/server.log"; fail "the image's health check"; }

python3 "$here/smoke.py" "http://127.0.0.1:$port" "$root/tests/data/envmaps" studio.hdr ||
  { cat "$work/server.log"; fail "the API smoke test"; }

owner="$(find "$work/state" -mindepth 1 -printf '%U\n' | sort -u)"
[ "$owner" = "$uid" ] || fail "state files owned by '$owner', expected uid $uid"
find "$work/state" -name '*forest*' | grep -q . || fail "the uploaded map is not in the /state volume"
echo "the /state volume holds the uploads, owned by uid $uid"

# buildah run answers SIGTERM by killing what it runs: the signal goes to the server process itself.
server_process() {
  local pids=("$1") pid
  while [ ${#pids[@]} -gt 0 ]; do
    pid="${pids[0]}"
    pids=("${pids[@]:1}")
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = lightprobe-serv ] && echo "$pid" && return
    mapfile -t -O "${#pids[@]}" pids < <(pgrep -P "$pid")
  done
}
pid="$(server_process "$server")"
[ -n "$pid" ] || fail "no lightprobe-server process under buildah run ($server)"
kill -TERM "$pid"
status=0
wait "$server" || status=$?
server=""
[ "$status" = 0 ] || { cat "$work/server.log"; fail "the server exited $status on SIGTERM"; }
grep -q "stopped" "$work/server.log" || { cat "$work/server.log"; fail "no orderly stop on SIGTERM"; }
echo "SIGTERM: stopped, exit 0"
echo "container test passed"
