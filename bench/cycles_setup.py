"""The Cycles set-up lightprobe's comparisons share (bench/cycles_compare.py, bench/fidelity/): render
settings that match a lightprobe render (no clamping, no denoising, no adaptive sampling, box pixel
filter, every caustic), a world of a lat-long map with lightprobe's convention, and a camera of a
lightprobe render request. Runs inside Blender's Python.
"""
import math
import os
import sys

import bpy
from mathutils import Vector


def configure_cycles(scene, width, height, threads, bounces=8):
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
    cycles.max_bounces = bounces
    cycles.diffuse_bounces = bounces
    cycles.glossy_bounces = bounces
    cycles.transmission_bounces = bounces
    cycles.volume_bounces = bounces
    # lightprobe passes cut-out and blended surfaces without spending a bounce
    cycles.transparent_max_bounces = 256
    cycles.filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.seed = 1
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = False
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGBA"


def add_world_map(scene, map_path, interpolation="Closest"):
    world = bpy.data.worlds.new("map")
    scene.world = world
    world.use_nodes = True
    nodes = world.node_tree.nodes
    env = nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.abspath(map_path))
    env.interpolation = interpolation
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


def add_camera(scene, spec):
    """A lightprobe camera (position, look_at, up = +z, vertical fov_deg) as the scene's camera."""
    if [float(c) for c in spec.get("up", (0, 0, 1))] != [0.0, 0.0, 1.0]:
        sys.exit("cycles_setup.py: only cameras with up = [0, 0, 1] are translated")
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle = math.radians(spec.get("fov_deg", 40.0))
    cam_data.clip_start = 1e-3
    cam_data.clip_end = 1e6
    cam = bpy.data.objects.new("camera", cam_data)
    scene.collection.objects.link(cam)
    cam.location = spec["position"]
    view = Vector(spec["look_at"]) - Vector(spec["position"])
    cam.rotation_euler = view.to_track_quat("-Z", "Y").to_euler()
    scene.camera = cam


def render_pixels(scene, spp, seed, path):
    """Renders to the EXR at path and returns its RGBA floats (rows bottom to top)."""
    scene.cycles.samples = spp
    scene.cycles.seed = seed
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return load_pixels(path)


def load_pixels(path):
    img = bpy.data.images.load(path)
    pixels = list(img.pixels[:])
    bpy.data.images.remove(img)
    return pixels


def rel_mse(a, b, covered=None):
    """mean((a-b)^2) / mean(b)^2 over RGB of RGBA pixels, of those `covered` says (all when None)."""
    sq = total = 0.0
    n = 0
    for p in range(0, len(b), 4):
        if covered is not None and not covered[p // 4]:
            continue
        for k in range(3):
            d = a[p + k] - b[p + k]
            sq += d * d
            total += b[p + k]
            n += 1
    if n == 0 or total == 0:
        return None
    return (sq / n) / (total / n) ** 2
