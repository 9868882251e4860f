"""Blender Cycles on lightprobe's `sphere` preset, for bench/render_error_bench: time to reach a given RMSE
against Cycles' own converged image.

The scene matches engine/render/scene_presets.cpp: a diffuse sphere (albedo 0.8, radius 1, a 256 x 128
smooth UV sphere since Cycles has no analytic sphere) at the origin, camera at (0, -4, 0) looking along +y
with a 40 degree vertical field, lit by forest.exr (no clamping, no denoising, no adaptive sampling, box
pixel filter, the map importance-sampled at its own resolution), transparent film (the camera does not see
the map), 8 bounces, CPU with a fixed thread count.

Needs Blender (Debian: apt-get install blender). Run:
  blender -b --factory-startup --python bench/cycles_compare.py -- \
      --map ../shared/data/envmaps/forest.exr --size 128 --ref-spp 8192 --max-spp 1024 --threads 2 [--out DIR]
Prints CSV: spp, seconds (bpy.ops.render.render wall time: scene sync, BVH, sampling), relative RMSE
(RMSE over the reference's covered pixels / their mean).
"""
import argparse
import math
import os
import sys
import tempfile
import time

import bpy


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--map", required=True)
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--ref-spp", type=int, default=8192)
    p.add_argument("--max-spp", type=int, default=1024)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--out", default="")
    return p.parse_args(argv)


def build_scene(args):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.max_bounces = 8
    cycles.diffuse_bounces = 8
    cycles.glossy_bounces = 8
    cycles.transmission_bounces = 8
    cycles.transparent_max_bounces = 8
    cycles.filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.seed = 1
    scene.render.film_transparent = True
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.resolution_x = scene.render.resolution_y = args.size
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = False
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGBA"

    world = bpy.data.worlds.new("forest")
    scene.world = world
    world.use_nodes = True
    nodes = world.node_tree.nodes
    env = nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.abspath(args.map))
    env.interpolation = "Closest"  # lightprobe looks the map up per pixel (nearest)
    # Cycles maps a direction of azimuth phi to u = 0.5 - phi / (2 pi); lightprobe to u = phi / (2 pi)
    # (engine/envmap/latlong.hpp). Mirroring x turns one into the other.
    coords = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "VECTOR"
    mapping.inputs["Scale"].default_value = (-1.0, 1.0, 1.0)
    world.node_tree.links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
    world.node_tree.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    world.node_tree.links.new(env.outputs["Color"], nodes["Background"].inputs["Color"])
    nodes["Background"].inputs["Strength"].default_value = 1.0
    world.cycles.sampling_method = "MANUAL"
    world.cycles.sample_map_resolution = env.image.size[0]

    bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=1.0, location=(0, 0, 0))
    sphere = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    mat = bpy.data.materials.new("diffuse")
    mat.use_nodes = True
    mnodes = mat.node_tree.nodes
    mnodes.clear()
    diffuse = mnodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (0.8, 0.8, 0.8, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    out = mnodes.new("ShaderNodeOutputMaterial")
    mat.node_tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
    sphere.data.materials.append(mat)

    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle = math.radians(40.0)
    cam = bpy.data.objects.new("camera", cam_data)
    scene.collection.objects.link(cam)
    cam.location = (0.0, -4.0, 0.0)
    cam.rotation_euler = (math.radians(90.0), 0.0, 0.0)  # looks along +y, z up
    scene.camera = cam
    return scene


def render(scene, spp, seed, path):
    scene.cycles.samples = spp
    scene.cycles.seed = seed
    scene.render.filepath = path
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - t0
    img = bpy.data.images.load(path)
    pixels = list(img.pixels[:])  # RGBA, rows bottom to top
    bpy.data.images.remove(img)
    return pixels, seconds


def relative_rmse(a, ref):
    sq = total = 0.0
    n = 0
    for i in range(0, len(ref), 4):
        if ref[i + 3] < 0.999:  # only fully covered pixels
            continue
        for k in range(3):
            d = a[i + k] - ref[i + k]
            sq += d * d
            total += ref[i + k]
            n += 1
    return math.sqrt(sq / n) / (total / n)


def main():
    args = parse_args()
    out = args.out or tempfile.mkdtemp(prefix="cycles_compare_")
    scene = build_scene(args)
    ref, ref_seconds = render(scene, args.ref_spp, 1000, os.path.join(out, "reference.exr"))
    print(f"# cycles sphere {args.size}x{args.size}, {args.threads} threads; reference {args.ref_spp} spp "
          f"in {ref_seconds:.2f} s", flush=True)
    print("spp,seconds,relative_rmse", flush=True)
    spp = 1
    while spp <= args.max_spp:
        img, seconds = render(scene, spp, 1, os.path.join(out, f"spp_{spp}.exr"))
        print(f"{spp},{seconds:.4f},{relative_rmse(img, ref):.5f}", flush=True)
        spp *= 2


main()
