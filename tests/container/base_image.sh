#!/usr/bin/env bash
# Makes the base images docker/Dockerfile starts from, debian:bookworm and debian:bookworm-slim, from
# Debian's own packages (debootstrap), on a machine whose podman cannot pull them from a registry.
# Nothing to do when both are in podman's image store (they stay there: this runs once per machine,
# about 1.5 minutes). Without debootstrap it leaves them to `podman build`, which pulls them.
set -euo pipefail

missing=0
for tag in bookworm bookworm-slim; do
  podman image exists "docker.io/library/debian:$tag" || missing=1
done
[ "$missing" = 0 ] && exit 0
if ! command -v debootstrap >/dev/null 2>&1; then
  echo "base_image: no local debian:bookworm images and no debootstrap; podman build will pull them"
  exit 0
fi

rootfs="$(mktemp -d /tmp/lightprobe-rootfs-XXXXXX)"
trap 'rm -rf "$rootfs"' EXIT
echo "base_image: debootstrap --variant=minbase bookworm"
nice debootstrap --variant=minbase bookworm "$rootfs" >"$rootfs.log" 2>&1 || {
  cat "$rootfs.log"
  exit 1
}
rm -f "$rootfs.log"
# As in the registry's images: no package lists, no downloaded packages.
rm -rf "$rootfs"/var/lib/apt/lists/* "$rootfs"/var/cache/apt/*.bin "$rootfs"/var/cache/apt/archives/*.deb
tar -C "$rootfs" -c . | podman import - docker.io/library/debian:bookworm

# The slim variant, as the registry's: no documentation (but copyrights), manual pages or translations,
# neither now nor from packages installed later.
cat >"$rootfs/etc/dpkg/dpkg.cfg.d/docker" <<'EOF'
path-exclude /usr/share/doc/*
path-include /usr/share/doc/*/copyright
path-exclude /usr/share/man/*
path-exclude /usr/share/groff/*
path-exclude /usr/share/info/*
path-exclude /usr/share/lintian/*
path-exclude /usr/share/linda/*
path-exclude /usr/share/locale/*
EOF
find "$rootfs/usr/share/doc" -type f ! -name copyright -delete
rm -rf "$rootfs"/usr/share/{man,groff,info,lintian,linda}/* "$rootfs"/usr/share/locale/*
tar -C "$rootfs" -c . | podman import - docker.io/library/debian:bookworm-slim
podman images docker.io/library/debian
