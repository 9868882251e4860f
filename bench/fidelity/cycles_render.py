"""Renders a glTF model with Cycles as a glTF consumer sees it (imported with Blender's glTF importer),
under a lat-long map with lightprobe's convention and from a lightprobe camera, and compares the
result with lightprobe's render of the same file. Runs inside Blender:
  blender -b --factory-startup --python bench/fidelity/cycles_render.py -- --model M.glb --map MAP.exr \
      --camera '{"position": [...], "look_at": [...], "fov_deg": 40}' --width 256 --height 256 --spp 512 \
      --bounces 16 --threads 2 --out cycles.exr [--compare lightprobe.exr]
Prints one line, "fidelity {json}": Cycles' seconds and, with --compare, relMSE = mean((a-b)^2)/mean(b)^2
over the whole image and over the pixels the model covers (alpha 1 in a transparent-film render), and
with --noise the same over the model's pixels between two Cycles renders of different seeds.
"""
import argparse
import json
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import cycles_setup  # noqa: E402


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--model", required=True)
    p.add_argument("--map", required=True)
    p.add_argument("--camera", required=True, help="a lightprobe camera as JSON")
    p.add_argument("--width", type=int, default=256)
    p.add_argument("--height", type=int, default=256)
    p.add_argument("--spp", type=int, default=512)
    p.add_argument("--mask-spp", type=int, default=16)
    p.add_argument("--bounces", type=int, default=16)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--out", required=True)
    p.add_argument("--compare", default="")
    p.add_argument("--noise", action="store_true", help="also render a second seed, for the noise floor")
    p.add_argument("--compare-seed2", default="", help="lightprobe's render of another seed: its noise floor")
    return p.parse_args(argv)


def allow_importer_numpy():
    """Blender 3.4's glTF importer asks NumPy for np.bool, which NumPy 1.24 (Debian 12's) no longer has."""
    import numpy
    if "bool" not in numpy.__dict__:
        numpy.bool = bool


def build_scene(args):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    cycles_setup.configure_cycles(scene, args.width, args.height, args.threads, args.bounces)
    # lightprobe filters the map seen by camera rays over their footprint; linear is the nearer match
    cycles_setup.add_world_map(scene, args.map, interpolation="Linear")
    allow_importer_numpy()
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(args.model))
    cycles_setup.add_camera(scene, json.loads(args.camera))
    return scene


def main():
    args = parse_args()
    scene = build_scene(args)
    scene.render.film_transparent = True
    mask = cycles_setup.render_pixels(scene, args.mask_spp, 7, args.out + ".mask.exr")
    covered = [mask[p + 3] >= 0.999 for p in range(0, len(mask), 4)]
    scene.render.film_transparent = False
    t0 = time.perf_counter()
    cycles = cycles_setup.render_pixels(scene, args.spp, 1, args.out)
    result = {"cycles_seconds": round(time.perf_counter() - t0, 2),
              "covered_fraction": round(sum(covered) / len(covered), 4)}
    if args.compare:
        ours = cycles_setup.load_pixels(os.path.abspath(args.compare))
        if len(ours) != len(cycles):
            sys.exit(f"cycles_render.py: {args.compare} is not {args.width} x {args.height}")
        result["relmse_image"] = cycles_setup.rel_mse(ours, cycles)
        result["relmse_model"] = cycles_setup.rel_mse(ours, cycles, covered)
        if args.noise:
            # Two Cycles images of different seeds differ by noise alone: what the comparison of two
            # unbiased renders of equal noise would measure.
            again = cycles_setup.render_pixels(scene, args.spp, 2, args.out + ".seed2.exr")
            result["relmse_noise"] = cycles_setup.rel_mse(again, cycles, covered)
        if args.compare_seed2:
            ours2 = cycles_setup.load_pixels(os.path.abspath(args.compare_seed2))
            result["relmse_noise_lightprobe"] = cycles_setup.rel_mse(ours2, ours, covered)
        result["mean_cycles_model"] = mean_rgb(cycles, covered)
        result["mean_lightprobe_model"] = mean_rgb(ours, covered)
        save_side_by_side(ours, cycles, args.width, args.height, args.out + ".side_by_side.png")
    print("fidelity " + json.dumps(result), flush=True)


def save_side_by_side(ours, cycles, width, height, path):
    """lightprobe | Cycles | |difference| x 4, as an sRGB PNG for looking at."""
    import numpy
    a = numpy.array(ours, dtype=numpy.float32).reshape(height, width, 4)
    b = numpy.array(cycles, dtype=numpy.float32).reshape(height, width, 4)
    diff = numpy.abs(a - b) * 4
    diff[..., 3] = 1
    panels = numpy.concatenate([a, b, diff], axis=1)
    panels[..., 3] = 1
    img = bpy.data.images.new("side_by_side", 3 * width, height, float_buffer=True)
    img.pixels[:] = panels.ravel()
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()


def mean_rgb(pixels, covered):
    sums = [0.0, 0.0, 0.0]
    n = 0
    for p in range(0, len(pixels), 4):
        if covered[p // 4]:
            n += 1
            for k in range(3):
                sums[k] += pixels[p + k]
    return [round(s / max(n, 1), 5) for s in sums]


main()
