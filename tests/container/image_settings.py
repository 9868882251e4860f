#!/usr/bin/env python3
"""The image's settings, run by the real server binary without a container: image_settings.py SERVER_BIN REPO.

docker/Dockerfile configures the server with LIGHTPROBE_* variables and an entrypoint without flags, so
that `docker run -e LIGHTPROBE_...` works (a flag in the entrypoint would win over every variable). This
reads the Dockerfile's ENV, ENTRYPOINT, HEALTHCHECK and LABELs and checks:
- each variable names a server flag, and the entrypoint passes no flag;
- the server started with the image's variables, some changed as `docker run -e` changes them (the port,
  the folders), listens where the variables say and keeps its state there;
- the image's HEALTHCHECK command, with the same variables, fails while the server loads and passes once
  it is ready (a map read from a FIFO decides when loading ends);
- the OCI labels are there, the version label is the project's version (cmake/version.cmake).
The container test (run.sh) checks the built image; this needs no podman, so every CI run has it.
"""
import json
import os
import re
import shlex
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

SERVER, REPO = sys.argv[1], sys.argv[2]


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def instructions(path):
    """The Dockerfile's instructions of the runtime stage (after the last FROM), continuation lines joined."""
    text = re.sub(r"\\\n", " ", open(path).read())
    lines = [l.strip() for l in text.splitlines() if l.strip() and not l.strip().startswith("#")]
    last_from = max(i for i, l in enumerate(lines) if l.startswith("FROM "))
    out = []
    for l in lines[last_from:]:
        word, _, rest = l.partition(" ")
        out.append((word.upper(), rest.strip()))
    return out


def key_values(rest):
    return dict(pair.split("=", 1) for pair in shlex.split(rest))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def grey_pfm(width, height):
    return b"PF\n%d %d\n-1.0\n" % (width, height) + struct.pack("<f", 0.5) * (3 * width * height)


def main():
    steps = instructions(os.path.join(REPO, "docker", "Dockerfile"))
    env, labels, args = {}, {}, {}
    entrypoint = health = None
    for word, rest in steps:
        if word == "ENV":
            env.update(key_values(rest))
        elif word == "LABEL":
            labels.update(key_values(rest))
        elif word == "ARG":
            name, _, default = rest.partition("=")
            args[name] = default
        elif word == "ENTRYPOINT":
            entrypoint = json.loads(rest)
        elif word == "HEALTHCHECK":
            health = json.loads(rest[rest.index("CMD") + 3:])
    if not entrypoint or not health:
        fail("no ENTRYPOINT or HEALTHCHECK in exec form")
    if [a for a in entrypoint[1:] if a.startswith("-")]:
        fail(f"the entrypoint passes flags, which win over LIGHTPROBE_ variables: {entrypoint}")
    for name in ("HOST", "PORT", "DATA_DIR", "STATE_DIR", "WEB_DIR"):
        if "LIGHTPROBE_" + name not in env:
            fail(f"no ENV LIGHTPROBE_{name}")
    usage = subprocess.run([SERVER, "--help"], capture_output=True, text=True).stdout
    for name in env:
        if name.startswith("LIGHTPROBE_") and name not in usage:
            fail(f"ENV {name} is no variable of lightprobe-server --help")
    for label in ("title", "description", "version", "revision", "created", "base.name"):
        if "org.opencontainers.image." + label not in labels:
            fail(f"no OCI label org.opencontainers.image.{label}")
    version = re.search(r"set\(LIGHTPROBE_VERSION ([^)\s]+)\)",
                        open(os.path.join(REPO, "cmake", "version.cmake")).read()).group(1)
    version_label = labels["org.opencontainers.image.version"]
    arg = re.fullmatch(r"\$\{?(\w+)\}?", version_label)
    if (args.get(arg.group(1)) if arg else version_label) != version:
        fail(f"the version label {version_label} is not the project's {version}")
    print("Dockerfile: variables", sorted(env), "entrypoint", entrypoint, "health check", health)

    with tempfile.TemporaryDirectory() as tmp:
        # As `docker run -e` changes them: the port, the folders; the rest stay the image's.
        run_env = dict(os.environ, **env)
        port = free_port()
        run_env.update(LIGHTPROBE_PORT=str(port), LIGHTPROBE_HOST="127.0.0.1",
                       LIGHTPROBE_DATA_DIR=os.path.join(REPO, "tests", "data", "envmaps"),
                       LIGHTPROBE_STATE_DIR=os.path.join(tmp, "state"),
                       LIGHTPROBE_WEB_DIR=os.path.join(REPO, "web"))
        fifo = os.path.join(tmp, "slow.pfm")
        os.mkfifo(fifo)
        run_env["LIGHTPROBE_LOAD"] = "slow=" + fifo
        log = open(os.path.join(tmp, "server.log"), "w+")
        server = subprocess.Popen([SERVER] + entrypoint[1:], env=run_env, stdout=log, stderr=subprocess.STDOUT)
        probe = [SERVER] + health[1:]
        try:
            deadline = time.time() + 60
            while f"listening on http://127.0.0.1:{port}" not in open(log.name).read():
                if server.poll() is not None or time.time() > deadline:
                    fail("the server did not listen where LIGHTPROBE_HOST and LIGHTPROBE_PORT say: " +
                         open(log.name).read())
                time.sleep(0.05)
            loading = subprocess.run(probe, env=run_env, capture_output=True, text=True)
            if loading.returncode != 1 or "status 503" not in loading.stderr:
                fail(f"the health check passed while the server loads: {loading.returncode} "
                     f"{loading.stdout}{loading.stderr}")
            threading.Thread(target=lambda: open(fifo, "wb").write(grey_pfm(8, 4))).start()
            deadline = time.time() + 60
            while True:
                ready = subprocess.run(probe, env=run_env, capture_output=True, text=True)
                if ready.returncode == 0:
                    break
                if time.time() > deadline:
                    fail(f"the health check never passed: {ready.stdout}{ready.stderr}")
                time.sleep(0.1)
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/v1/envmaps", timeout=10) as r:
                names = [m["name"] for m in json.load(r)["envmaps"]]
            if names != ["slow"]:
                fail(f"LIGHTPROBE_LOAD did not load the map: {names}")
            if not os.path.isdir(os.path.join(tmp, "state")):
                fail("LIGHTPROBE_STATE_DIR was not used")
            print(f"the image's settings serve on the variables' port {port}; health check 1 while "
                  f"loading, 0 when ready")
        finally:
            server.terminate()
            server.wait(timeout=30)
    print("image settings passed")


main()
