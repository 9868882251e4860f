#!/usr/bin/env python3
"""The API smoke test, against any running server: smoke.py BASE_URL DATA_DIR MAP_IN_DATA_DIR.

Health; a map uploaded (DATA_DIR/forest.exr) and one loaded by its path inside the server's --data-dir;
importance samples; median-cut lights; a Fresnel table; a small render to done. Values are checked
against what they must be analytically, with the tolerances stated beside each check.
"""
import json
import math
import struct
import sys
import time
import urllib.error
import urllib.request

BASE = sys.argv[1].rstrip("/") + "/api/v1"
DATA_DIR = sys.argv[2]
MAP_IN_DATA_DIR = sys.argv[3]


def request(method, path, body=None, content_type=None):
    headers = {"Content-Type": content_type} if content_type else {}
    req = urllib.request.Request(BASE + path, data=body, method=method, headers=headers)
    try:
        with urllib.request.urlopen(req, timeout=120) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


def call(method, path, expected, body=None, content_type=None):
    status, data = request(method, path, body, content_type)
    if status != expected:
        raise AssertionError(f"{method} {path}: {status}, expected {expected}: {data[:500]!r}")
    return data


def post_json(path, value, expected):
    return json.loads(call("POST", path, expected, json.dumps(value).encode(), "application/json"))


def check(condition, what):
    if not condition:
        raise AssertionError(what)


def near(a, b, tolerance, what):
    check(abs(a - b) <= tolerance, f"{what}: {a} differs from {b} by more than {tolerance}")


def constant_pfm(width, height, value):
    header = f"PF\n{width} {height}\n-1.0\n".encode()
    return header + struct.pack(f"<{width * height * 3}f", *([value] * (width * height * 3)))


def read_pfm(data):
    """(width, height, pixel(x, y) -> (r, g, b)) of a little-endian colour PFM, y from the top."""
    parts = data.split(b"\n", 3)
    check(parts[0] == b"PF" and float(parts[2]) < 0, f"not a little-endian colour PFM: {data[:32]!r}")
    width, height = map(int, parts[1].split())
    floats = struct.unpack(f"<{width * height * 3}f", parts[3][: width * height * 12])

    def pixel(x, y):  # PFM rows run bottom to top
        i = ((height - 1 - y) * width + x) * 3
        return floats[i : i + 3]

    return width, height, pixel


def health():
    h = json.loads(call("GET", "/health", 200))
    check(h["status"] == "ok", f"health: {h}")
    print(f"health: ok, version {h['version']}")


def load_maps():
    with open(f"{DATA_DIR}/forest.exr", "rb") as f:
        forest = json.loads(call("POST", "/envmaps?name=forest", 201, f.read(), "application/octet-stream"))
    check((forest["width"], forest["height"], forest["format"]) == (256, 128, "exr"), f"upload: {forest}")
    by_path = post_json("/envmaps", {"name": "by_path", "path": MAP_IN_DATA_DIR}, 201)
    check(by_path["source"] == "path:" + MAP_IN_DATA_DIR, f"load by path: {by_path}")
    names = {m["name"] for m in json.loads(call("GET", "/envmaps", 200))["envmaps"]}
    check({"forest", "by_path"} <= names, f"maps listed: {names}")
    print(f"maps: forest uploaded, by_path loaded from {MAP_IN_DATA_DIR}")
    return forest


def samples():
    body = {"count": 64, "seed": 7, "strategy": "stratified"}
    first = post_json("/envmaps/forest/samples", body, 200)["samples"]
    again = post_json("/envmaps/forest/samples", body, 200)["samples"]
    check(len(first) == 64 and first == again, "64 samples, the same for the same seed")
    for s in first:
        d = s["direction"]
        near(math.hypot(*d), 1.0, 1e-5, "a sample direction's length")
        near(d[2], math.cos(s["theta"]), 1e-5, "z = cos(theta) (z-up)")
        check(s["pdf"] > 0 and 0 <= s["uv"][0] < 1 and 0 <= s["uv"][1] < 1, f"sample: {s}")
    print("samples: 64 unit directions with z = cos(theta), positive pdf, reproducible")


def median_cut(forest):
    result = post_json("/envmaps/forest/median-cut", {"count": 16}, 200)
    check(len(result["lights"]) == 16, f"16 lights: {len(result['lights'])}")
    for c in range(3):  # the lights partition the map: their powers sum to its power (float sums)
        total = sum(light["power"][c] for light in result["lights"])
        near(total, forest["power"][c], 1e-5 * forest["power"][c], f"channel {c} of the lights' power")
    print("median cut: 16 lights whose powers sum to the map's power within 1e-5")


def fresnel():
    table = json.loads(call("GET", "/fresnel?eta_i=1.0&eta_t=1.5&step=1", 200))
    near(table["r0"], (0.5 / 2.5) ** 2, 1e-12, "R0 of air to glass 1.5")
    near(table["brewster_deg"], math.degrees(math.atan(1.5)), 1e-8, "Brewster's angle")
    check(table["unpolarized"][90] == 1.0, "R = 1 at grazing incidence")
    print("fresnel: R0 = 0.04, Brewster 56.31 deg, R(90) = 1")


def render():
    """The furnace preset (a diffuse sphere of albedo 0.5) in a constant map of radiance 1: the
    background is exactly 1 and every pixel on the sphere 0.5 in expectation (a convex diffuse object
    sees only the map). The sphere spans ~11.3 px around the centre of a 32 px image; the ~250 pixels
    within 9 px of it, at 64 spp, have a mean with a standard error under 0.65 / sqrt(250 x 64) = 0.005
    (0.65: the standard deviation of a sample of the map alone), so 0.03 is 6 sigma."""
    call("POST", "/envmaps?name=white", 201, constant_pfm(64, 32, 1.0), "application/octet-stream")
    job = post_json("/renders", {"envmap": "white", "scene": {"preset": "furnace"}, "width": 32,
                                 "height": 32, "spp": 64}, 202)
    deadline = time.monotonic() + 300
    while True:
        status = json.loads(call("GET", f"/renders/{job['id']}", 200))
        if status["status"] not in ("queued", "running"):
            break
        check(time.monotonic() < deadline, f"render still {status['status']} after 300 s")
        time.sleep(0.1)
    check(status["status"] == "done", f"render: {status}")
    width, height, pixel = read_pfm(call("GET", f"/renders/{job['id']}/image?format=pfm", 200))
    check((width, height) == (32, 32), f"image size {width}x{height}")
    for x, y in [(0, 0), (31, 0), (0, 31), (31, 31)]:
        for c in pixel(x, y):
            near(c, 1.0, 1e-5, f"background pixel ({x}, {y})")
    disc = [(x, y) for y in range(32) for x in range(32) if math.hypot(x + 0.5 - 16, y + 0.5 - 16) < 9]
    mean = sum(sum(pixel(x, y)) / 3 for x, y in disc) / len(disc)
    near(mean, 0.5, 0.03, f"the mean of the {len(disc)} pixels on the furnace sphere")
    png = call("GET", f"/renders/{job['id']}/image?format=png", 200)
    check(png.startswith(b"\x89PNG\r\n\x1a\n"), "a PNG image")
    print(f"render: done; furnace sphere {mean:.4f} (0.5 within 0.03), background 1 within 1e-5, PNG served")


health()
forest = load_maps()
samples()
median_cut(forest)
fresnel()
render()
print("smoke test passed")
