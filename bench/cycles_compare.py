"""Blender Cycles on a lightprobe scene, for bench/render_error_bench and bench/embree_share.sh: time to
reach a given RMSE against Cycles' own converged image, or one render's time.

The default scene matches the `sphere` preset of engine/render/scene_presets.cpp: a diffuse sphere (albedo
0.8, radius 1) at the origin, camera at (0, -4, 0) looking along +y with a 40 degree vertical field.
`--scene FILE.json` renders instead the scene of a lightprobe render request file (bench/scenes): its
camera (z up), and its spheres, planes and meshes (.obj), all diffuse. Cycles has no analytic sphere: a
sphere is a 256 x 128 smooth UV sphere; a plane is a square 1000 units wide. Both are lit by the map (no
clamping, no denoising, no adaptive sampling, box pixel filter, the map importance-sampled at its own
resolution), with a transparent film (the camera does not see the map), 8 bounces, CPU with a fixed
thread count.

Needs Blender (Debian: apt-get install blender). Run:
  blender -b --factory-startup --python bench/cycles_compare.py -- \
      --map ../shared/data/envmaps/forest.exr --size 128 --ref-spp 8192 --max-spp 1024 --threads 2 \
      [--scene bench/scenes/bunny.json] [--out DIR]
Prints CSV: spp, seconds (bpy.ops.render.render wall time: scene sync, BVH, sampling), relative RMSE
(RMSE over the reference's covered pixels / their mean). With `--once SPP` it renders once at SPP and
prints only "seconds,S".
"""
import argparse
import json
import math
import os
import sys
import tempfile
import time

import bpy
from mathutils import Euler, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_setup  # noqa: E402


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--map", required=True)
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--ref-spp", type=int, default=8192)
    p.add_argument("--max-spp", type=int, default=1024)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--scene", default="")
    p.add_argument("--once", type=int, default=0)
    p.add_argument("--out", default="")
    return p.parse_args(argv)


SPHERE_PRESET = {"scene": {
    "camera": {"position": [0, -4, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov_deg": 40},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "albedo": 0.8}}]}}


def load_request(path):
    with open(path) as f:
        request = json.load(f)
    if "preset" in request["scene"]:
        sys.exit("cycles_compare.py: --scene takes a scene of objects, not a preset")
    return request


def diffuse_material(spec, name):
    if spec.get("type") != "diffuse":
        sys.exit(f"cycles_compare.py: {name}: only diffuse materials are translated, not {spec.get('type')}")
    albedo = spec.get("albedo", 0.8)
    rgb = albedo if isinstance(albedo, list) else [albedo] * 3
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*rgb, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    out = nodes.new("ShaderNodeOutputMaterial")
    mat.node_tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
    return mat


def add_object(spec, folder, name):
    kind = spec["type"]
    if kind == "sphere":
        bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=spec.get("radius", 1.0),
                                             location=spec.get("center", (0, 0, 0)))
        bpy.ops.object.shade_smooth()
    elif kind == "plane":
        bpy.ops.mesh.primitive_plane_add(size=1000, location=spec.get("point", (0, 0, 0)))
        normal = Vector(spec.get("normal", (0, 0, 1))).normalized()
        bpy.context.active_object.rotation_euler = normal.to_track_quat("Z", "Y").to_euler()
    elif kind == "mesh":
        # The file's up axis as lightprobe reads it (y: (x, y, z) -> (x, -z, y), Blender's default; z: as
        # it is); then scale, rotations about x, y, z, translation.
        axes = {"y": ("NEGATIVE_Z", "Y"), "z": ("Y", "Z")}[spec.get("up_axis", "y")]
        bpy.ops.wm.obj_import(filepath=os.path.join(folder, spec["path"]), forward_axis=axes[0], up_axis=axes[1])
        bpy.context.view_layer.objects.active = bpy.context.selected_objects[0]
        t = spec.get("transform", {})
        o = bpy.context.active_object
        o.scale = [t.get("scale", 1.0)] * 3
        o.rotation_euler = Euler([math.radians(a) for a in t.get("rotate_deg", (0, 0, 0))], "XYZ")
        o.location = t.get("translate", (0, 0, 0))
    else:
        sys.exit(f"cycles_compare.py: {name}: no translation for objects of type {kind}")
    obj = bpy.context.active_object
    obj.data.materials.clear()
    obj.data.materials.append(diffuse_material(spec.get("material", {"type": "diffuse"}), name))


def build_scene(args):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    cycles_setup.configure_cycles(scene, args.size, args.size, args.threads)
    scene.render.film_transparent = True
    cycles_setup.add_world_map(scene, args.map)  # lightprobe looks the map up per pixel (nearest)

    request = load_request(args.scene) if args.scene else SPHERE_PRESET
    folder = os.path.dirname(os.path.abspath(args.scene)) if args.scene else ""
    for i, obj in enumerate(request["scene"]["objects"]):
        add_object(obj, folder, f"object{i}")
    cycles_setup.add_camera(scene, request["scene"].get("camera", SPHERE_PRESET["scene"]["camera"]))
    return scene


def render(scene, spp, seed, path):
    t0 = time.perf_counter()
    pixels = cycles_setup.render_pixels(scene, spp, seed, path)
    return pixels, time.perf_counter() - t0


def relative_rmse(a, ref):
    """RMSE over the reference's fully covered pixels, relative to their mean."""
    covered = [ref[p + 3] >= 0.999 for p in range(0, len(ref), 4)]
    return math.sqrt(cycles_setup.rel_mse(a, ref, covered))


def main():
    args = parse_args()
    out = args.out or tempfile.mkdtemp(prefix="cycles_compare_")
    scene = build_scene(args)
    if args.once:
        _, seconds = render(scene, args.once, 1, os.path.join(out, f"once_{args.once}.exr"))
        print(f"seconds,{seconds:.4f}", flush=True)
        return
    ref, ref_seconds = render(scene, args.ref_spp, 1000, os.path.join(out, "reference.exr"))
    print(f"# cycles {args.scene or 'sphere'} {args.size}x{args.size}, {args.threads} threads; reference {args.ref_spp} spp "
          f"in {ref_seconds:.2f} s", flush=True)
    print("spp,seconds,relative_rmse", flush=True)
    spp = 1
    while spp <= args.max_spp:
        img, seconds = render(scene, spp, 1, os.path.join(out, f"spp_{spp}.exr"))
        print(f"{spp},{seconds:.4f},{relative_rmse(img, ref):.5f}", flush=True)
        spp *= 2


main()
