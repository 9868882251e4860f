#!/usr/bin/env python3
"""The denoiser's worth in error and time, with the command-line tool only.

For each scene (the `materials` preset, and a textured glTF model framed by the default camera), on one
map: a converged reference at REF_SPP (a seed of its own, so that no render shares its samples); renders
at 4, 16 and 64 spp with their albedo and normal passes, denoised by `lightprobe denoise` (OIDN's
rt_hdr_alb_nrm); raw renders at 64, 256 and 1024 spp. Prints each image's relMSE against the reference,
the mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01) (the relative MSE of the denoising
literature, Rousselle et al. 2011), and the wall time of each render and denoise. The reference's own
noise is in every figure: about the raw 1024 spp figure times 1024 / REF_SPP.

    bench/denoise_quality.py [--build build] [--size 256] [--ref-spp 4096] [--map tests/data/envmaps/forest.exr]
"""
import argparse
import array
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"


def read_pfm(path):
    """Linear RGB floats of a colour PFM, row order as stored (only compared pixel by pixel)."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        if kind != b"PF":
            raise ValueError(f"{path}: not a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        values = array.array("f")
        values.frombytes(f.read(width * height * 12))
        if (scale < 0) != (sys.byteorder == "little"):
            values.byteswap()
        return values


def rel_mse(image, reference):
    total = 0.0
    for x, r in zip(image, reference):
        total += (x - r) ** 2 / (r * r + 0.01)
    return total / len(reference)


def run(command):
    start = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


class Scene:
    def __init__(self, name, source, args, work):
        self.name, self.source, self.args, self.work = name, source, args, work

    def render(self, spp, out, passes=False, seed=0):
        command = [self.args.lightprobe, "render", self.source, "--width", str(self.args.size),
                   "--height", str(self.args.size), "--spp", str(spp), "--seed", str(seed), "-q", "-o", out]
        if self.source.endswith(".glb"):
            command += ["--envmap", self.args.map]
        if passes:
            command += ["--passes", "albedo,normal"]
        return run(command)

    def denoise(self, noisy, out):
        stem = noisy[: -len(".pfm")]
        return run([self.args.lightprobe, "denoise", noisy, "--albedo", stem + ".albedo.pfm",
                    "--normal", stem + ".normal.pfm", "-o", out])

    def study(self):
        reference_path = os.path.join(self.work, f"{self.name}_ref.pfm")
        seconds = self.render(self.args.ref_spp, reference_path, seed=1)  # samples of its own
        print(f"{self.name}: reference {self.args.ref_spp} spp, {seconds:.1f} s", flush=True)
        reference = read_pfm(reference_path)
        rows = []
        for spp in (4, 16, 64):
            noisy = os.path.join(self.work, f"{self.name}_{spp}.pfm")
            denoised = os.path.join(self.work, f"{self.name}_{spp}_denoised.pfm")
            render_s = self.render(spp, noisy, passes=True)
            denoise_s = self.denoise(noisy, denoised)
            rows.append((f"denoised {spp} spp", rel_mse(read_pfm(denoised), reference), render_s, denoise_s))
            rows.append((f"raw {spp} spp", rel_mse(read_pfm(noisy), reference), render_s, 0.0))
        for spp in (256, 1024):
            raw = os.path.join(self.work, f"{self.name}_{spp}.pfm")
            render_s = self.render(spp, raw)
            rows.append((f"raw {spp} spp", rel_mse(read_pfm(raw), reference), render_s, 0.0))
        print(f"| {self.name} {self.args.size}x{self.args.size} | relMSE | render s | denoise s |")
        print("|---|---|---|---|")
        for label, error, render_s, denoise_s in rows:
            print(f"| {label} | {error:.5f} | {render_s:.2f} | {denoise_s:.2f} |")
        print(flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--ref-spp", type=int, default=4096)
    parser.add_argument("--map", default=os.path.join(ROOT, "tests/data/envmaps/forest.exr"))
    parser.add_argument("--scenes", default="materials,model")
    args = parser.parse_args()
    args.lightprobe = os.path.join(args.build, "bin", "lightprobe")
    args.map = os.path.abspath(args.map)
    with tempfile.TemporaryDirectory() as work:
        materials = os.path.join(work, "materials.json")
        with open(materials, "w") as f:
            json.dump({"envmap": args.map, "scene": {"preset": "materials"}}, f)
        sources = {"materials": materials, "model": MODEL}
        for name in args.scenes.split(","):
            Scene(name, sources[name], args, work).study()


if __name__ == "__main__":
    main()
