#!/usr/bin/env python3
"""Fidelity against Blender Cycles: each test model rendered by lightprobe and by Cycles from the same
file, map and camera, and their relMSE = mean((a-b)^2)/mean(b)^2.

1. Blender builds the models and exports them with its glTF exporter (build_models.py); assimp's
   ClearCoat, TextureTransformTest and 2CylinderEngine join them (Debian's assimp-testmodels).
2. A real lightprobe-server takes each file as a user's upload (POST /api/v1/assets: its warnings are
   shown) and renders it framed by its default camera (no camera given).
3. Blender imports the same file with its glTF importer and Cycles renders it from the camera the job
   status reports (cycles_render.py), under the map with lightprobe's lat-long convention.

Needs Blender and NumPy for its glTF add-on (Debian: apt-get install blender python3-numpy; not part of
the setup) and a built tree. Run from the repository:
  python3 bench/fidelity/run.py --map ../shared/data/envmaps/forest.exr [--size 256] [--spp 512]
      [--cycles-spp 512] [--threads 2] [--no-mipmaps] [--only NAME ...] [--out DIR]
Prints a Markdown table: relMSE over the pixels the model covers, the noise floors (the same between two
Cycles renders of different seeds, and between two lightprobe renders; two unbiased renders differ
by about the mean of the two), relMSE over the whole image (where the map, seen directly, matches
by construction), the model pixels' mean colour in each, both renderers' times and the warnings of the
upload and the render. Beside the images, NAME.cycles.exr.side_by_side.png shows lightprobe | Cycles |
4 x |difference|.
"""
import argparse
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import urllib.error
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
ASSIMP = "/usr/share/assimp/models/glTF2"
BUILT = ["suzanne_textured", "sphere_grid", "normal_mapped_box", "emissive_panels", "alpha_leaf",
         "glass_sphere", "frosted_glass_sphere", "clearcoat_sphere", "vertex_colours"]
ASSIMP_MODELS = {  # name: (folder with every file of the model, model file)
    "ClearCoat": ("ClearCoat-glTF", "ClearCoatTest.gltf"),
    "TextureTransformTest": ("textureTransform", "TextureTransformTest.gltf"),
    "2CylinderEngine": ("2CylinderEngine-glTF-Binary", "2CylinderEngine.glb"),
}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--map", required=True)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--spp", type=int, default=512, help="lightprobe's samples per pixel")
    p.add_argument("--cycles-spp", type=int, default=512)
    p.add_argument("--bounces", type=int, default=16)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--no-mipmaps", action="store_true", help="lightprobe reads textures at level 0")
    p.add_argument("--only", nargs="*", default=[])
    p.add_argument("--out", default="")
    p.add_argument("--server", default=os.path.join(REPO, "build/bin/lightprobe-server"))
    p.add_argument("--blender", default="blender")
    return p.parse_args()


def blender_environment():
    """This environment without a Python version manager's paths, which would lead Blender's own Python
    (and its add-ons' NumPy) astray."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYENV")}
    env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep) if ".pyenv" not in p)
    return env


def blender(args, script, *script_args):
    cmd = [args.blender, "-b", "--factory-startup", "--python", os.path.join(HERE, script), "--", *script_args]
    run = subprocess.run(cmd, capture_output=True, text=True, env=blender_environment())
    if run.returncode != 0 or "Traceback" in run.stderr + run.stdout:
        sys.exit(f"{script} failed:\n{run.stdout[-3000:]}\n{run.stderr[-3000:]}")
    return run.stdout


def upload_body(name, out):
    """The bytes a user uploads: a .glb as it is, a .gltf with its files as a tar."""
    if name in BUILT:
        return open(os.path.join(out, name + ".glb"), "rb").read()
    folder, model = ASSIMP_MODELS[name]
    path = os.path.join(ASSIMP, folder)
    if model.endswith(".glb"):
        return open(os.path.join(path, model), "rb").read()
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w") as tar:
        for f in sorted(os.listdir(path)):
            tar.add(os.path.join(path, f), arcname=f)
    return buffer.getvalue()


def model_file(name, out):
    if name in BUILT:
        return os.path.join(out, name + ".glb")
    folder, model = ASSIMP_MODELS[name]
    return os.path.join(ASSIMP, folder, model)


class Server:
    def __init__(self, args, state):
        cmd = [args.server, "--port", "0", "--log-level", "warn", "--state-dir", state,
               "--threads", str(args.threads), "--load", f"map={os.path.abspath(args.map)}"]
        self.process = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        match = re.search(r"listening on (http://\S+)", line)
        if not match:
            self.process.kill()
            sys.exit(f"lightprobe-server did not start: {line}")
        self.base = match.group(1) + "/api/v1"
        self.wait_ready()

    def wait_ready(self):
        for _ in range(600):
            try:
                with urllib.request.urlopen(self.base + "/ready"):
                    return
            except (urllib.error.URLError, ConnectionError):
                time.sleep(0.1)
        sys.exit("lightprobe-server did not get ready in 60 s")

    def call(self, method, path, body=None, content_type="application/json"):
        data = json.dumps(body).encode() if isinstance(body, dict) else body
        request = urllib.request.Request(self.base + path, data=data, method=method,
                                         headers={"Content-Type": content_type} if data else {})
        try:
            with urllib.request.urlopen(request) as response:
                raw = response.read()
        except urllib.error.HTTPError as e:
            sys.exit(f"{method} {path}: {e.code} {e.read().decode()}")
        return raw if path.endswith("format=exr") else json.loads(raw)

    def stop(self):
        self.process.terminate()
        self.process.wait()


def render_here(server, args, name, body, folder):
    asset = server.call("POST", f"/assets?name={name}", body, "application/octet-stream")
    job, image = render_seed(server, args, name, 0, os.path.join(folder, f"{name}.lightprobe.exr"))
    render_seed(server, args, name, 1, os.path.join(folder, f"{name}.lightprobe.seed2.exr"))
    return asset, job, image


def render_seed(server, args, name, seed, image):
    request = {"envmap": "map", "width": args.size, "height": args.size, "spp": args.spp, "seed": seed,
               "max_depth": args.bounces, "mipmaps": not args.no_mipmaps, "scene": {"objects": [{"type": "mesh", "path": f"assets/{name}"}]}}
    job = server.call("POST", "/renders", request)
    while job["status"] in ("queued", "running"):
        time.sleep(0.5)
        job = server.call("GET", f"/renders/{job['id']}")
    if job["status"] != "done":
        sys.exit(f"{name}: render {job['status']}: {job.get('error')}")
    with open(image, "wb") as f:
        f.write(server.call("GET", f"/renders/{job['id']}/image?format=exr"))
    return job, image


def render_cycles(args, name, camera, compare, folder):
    out = blender(args, "cycles_render.py", "--model", model_file(name, folder), "--map", args.map,
                  "--camera", json.dumps(camera), "--width", str(args.size), "--height", str(args.size),
                  "--spp", str(args.cycles_spp), "--bounces", str(args.bounces), "--threads", str(args.threads),
                  "--out", os.path.join(folder, f"{name}.cycles.exr"), "--compare", compare, "--noise",
                  "--compare-seed2", compare.replace(".lightprobe.exr", ".lightprobe.seed2.exr"))
    return json.loads(out.split("fidelity ", 1)[1].splitlines()[0])


def main():
    args = parse_args()
    folder = args.out or tempfile.mkdtemp(prefix="fidelity_")
    os.makedirs(folder, exist_ok=True)
    names = args.only or BUILT + list(ASSIMP_MODELS)
    if any(n in BUILT for n in names):
        blender(args, "build_models.py", "--out", folder)
    state = os.path.join(folder, "state")
    shutil.rmtree(state, ignore_errors=True)
    server = Server(args, state)
    print(f"# {args.size}x{args.size}, lightprobe {args.spp} spp, Cycles {args.cycles_spp} spp, {args.bounces} "
          f"bounces, map {os.path.basename(args.map)}, {args.threads} threads; images in {folder}", flush=True)
    print("| model | triangles | relMSE (model pixels) | noise: Cycles, lightprobe | relMSE (image) | "
          "mean RGB, Cycles | mean RGB, lightprobe | lightprobe s | Cycles s | warnings |")
    print("|---|---|---|---|---|---|---|---|---|---|", flush=True)
    try:
        for name in names:
            asset, job, image = render_here(server, args, name, upload_body(name, folder), folder)
            camera = job["camera"]
            result = render_cycles(args, name, camera, image, folder)
            warnings = asset.get("warnings", []) + job.get("warnings", [])
            triangles = asset.get("triangles", "")
            rgb = lambda c: " ".join(f"{x:.3f}" for x in c)  # noqa: E731
            noise = f"{result['relmse_noise']:.4f}, {result['relmse_noise_lightprobe']:.4f}"
            print(f"| {name} | {triangles} | {result['relmse_model']:.4f} | {noise} | "
                  f"{result['relmse_image']:.4f} | {rgb(result['mean_cycles_model'])} | "
                  f"{rgb(result['mean_lightprobe_model'])} | {job['elapsed_s']:.1f} | "
                  f"{result['cycles_seconds']:.1f} | {'; '.join(warnings) or 'none'} |", flush=True)
            with open(os.path.join(folder, f"{name}.json"), "w") as f:
                json.dump({"asset": asset, "job": job, "cycles": result}, f, indent=1)
    finally:
        server.stop()


main()
