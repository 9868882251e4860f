"""The white furnace of Cycles' Principled BSDF, as Blender's glTF importer sets it up: a sphere under a
uniform white sky reflects its albedo, which an energy-conserving BSDF keeps at 1 or below (lightprobe's
glTF BSDF: 1 within 5e-3 for a white dielectric, tests/unit). Where Cycles measures above 1, the
fidelity table's differences on white, rough dielectrics are Cycles' energy gain, not lightprobe's loss.
Runs inside Blender:
  blender -b --factory-startup --python bench/fidelity/principled_furnace.py -- [--size 64] [--spp 256]
Prints CSV: case, mean of the sphere's pixels (RGB averaged).
"""
import argparse
import os
import sys

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import cycles_setup  # noqa: E402

CASES = {  # Principled inputs; everything else at the importer's values
    "white, roughness 0.5": {"Roughness": 0.5},
    "white, roughness 1": {"Roughness": 1.0},
    "white, roughness 0.05": {"Roughness": 0.05},
    "white metal, roughness 0.5": {"Roughness": 0.5, "Metallic": 1.0},
    "white, roughness 0.5, clearcoat 1 (0.03)": {"Roughness": 0.5, "Clearcoat": 1.0,
                                                  "Clearcoat Roughness": 0.03},
    "white, roughness 0.5, sheen 1": {"Roughness": 0.5, "Sheen": 1.0},
}


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--size", type=int, default=64)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--out", default="/tmp")
    return p.parse_args(argv)


def furnace(args, inputs, path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    cycles_setup.configure_cycles(scene, args.size, args.size, args.threads, bounces=64)
    world = bpy.data.worlds.new("white")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1, 1, 1, 1)
    scene.world = world
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=1)
    sphere = bpy.context.active_object
    for poly in sphere.data.polygons:
        poly.use_smooth = True
    mat = bpy.data.materials.new("furnace")
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (1, 1, 1, 1)
    bsdf.inputs["Metallic"].default_value = 0.0
    for key, value in inputs.items():
        bsdf.inputs[key].default_value = value
    sphere.data.materials.append(mat)
    cycles_setup.add_camera(scene, {"position": [0, -4, 0], "look_at": [0, 0, 0], "fov_deg": 30})
    scene.render.film_transparent = True
    pixels = cycles_setup.render_pixels(scene, args.spp, 1, path)
    covered = [p for p in range(0, len(pixels), 4) if pixels[p + 3] >= 0.999]
    return sum(sum(pixels[p:p + 3]) for p in covered) / (3 * len(covered))


def main():
    args = parse_args()
    print("case,furnace", flush=True)
    for i, (case, inputs) in enumerate(CASES.items()):
        print(f"{case},{furnace(args, inputs, os.path.join(args.out, f'furnace{i}.exr')):.4f}", flush=True)


main()
