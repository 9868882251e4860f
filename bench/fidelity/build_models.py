"""Builds the fidelity test models in Blender and exports each with Blender's glTF exporter (.glb), as an
artist's asset reaches lightprobe. Runs inside Blender:
  blender -b --factory-startup --python bench/fidelity/build_models.py -- --out DIR
Each model is built in a scene of its own in Blender's frame (z up, front towards -y); the exporter turns
it into glTF's (y up). Textures are drawn here, so nothing but Blender is needed.
"""
import argparse
import math
import os
import sys

import bpy


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--out", required=True)
    return p.parse_args(argv)


def empty_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def principled(name, **inputs):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    for key, value in inputs.items():
        bsdf.inputs[key].default_value = value
    return mat, bsdf


def assign(obj, mat):
    obj.data.materials.clear()
    obj.data.materials.append(mat)


def smooth(obj, subdivisions=0):
    if subdivisions:
        mod = obj.modifiers.new("subdivision", "SUBSURF")
        mod.levels = mod.render_levels = subdivisions
    for poly in obj.data.polygons:
        poly.use_smooth = True


def image(name, folder, size, texel):
    """A PNG drawn texel by texel: texel(u, v) -> (r, g, b, a) in [0, 1], v up."""
    img = bpy.data.images.new(name, size, size, alpha=True)
    pixels = [0.0] * (size * size * 4)
    for j in range(size):
        for i in range(size):
            k = 4 * (j * size + i)
            pixels[k:k + 4] = texel((i + 0.5) / size, (j + 0.5) / size)
    img.pixels[:] = pixels
    img.filepath_raw = os.path.join(folder, name + ".png")
    img.file_format = "PNG"
    img.save()
    return img


def texture_node(mat, img, non_color=False):
    node = mat.node_tree.nodes.new("ShaderNodeTexImage")
    node.image = img
    if non_color:
        img.colorspace_settings.name = "Non-Color"
    return node


def export(path):
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLB", export_apply=True, export_cameras=False,
                              export_lights=False)


def checker(u, v, n=8):
    on = (int(u * n) + int(v * n)) % 2 == 0
    return (0.9, 0.75, 0.2, 1.0) if on else (0.1, 0.25, 0.6, 1.0)


def textured_suzanne(folder):
    bpy.ops.mesh.primitive_monkey_add(size=2)
    obj = bpy.context.active_object
    smooth(obj, 2)
    mat, bsdf = principled("suzanne", Roughness=0.45)
    tex = texture_node(mat, image("suzanne_checker", folder, 256, checker))
    mat.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    assign(obj, mat)


def sphere_grid(folder):
    """Metallic 0 to 1 from bottom to top row, roughness 0.05 to 1 from left to right."""
    n = 5
    for row in range(n):
        for col in range(n):
            bpy.ops.mesh.primitive_uv_sphere_add(segments=64, ring_count=32, radius=0.42,
                                                 location=(col - (n - 1) / 2, 0, row - (n - 1) / 2))
            obj = bpy.context.active_object
            smooth(obj)
            mat, _ = principled(f"m{row}r{col}", **{"Base Color": (0.95, 0.64, 0.54, 1.0),
                                                     "Metallic": row / (n - 1),
                                                     "Roughness": 0.05 + 0.95 * col / (n - 1)})
            assign(obj, mat)


def bumps_normal(u, v, n=6):
    """A tangent-space normal map of a height field of rounded bumps, encoded as glTF's (x, y up)."""
    h = 0.35
    x = math.sin(2 * math.pi * n * u)
    y = math.sin(2 * math.pi * n * v)
    dhdu = h * 2 * math.pi * n * math.cos(2 * math.pi * n * u) * y / n / 4
    dhdv = h * 2 * math.pi * n * x * math.cos(2 * math.pi * n * v) / n / 4
    nx, ny, nz = -dhdu, -dhdv, 1.0
    length = math.sqrt(nx * nx + ny * ny + nz * nz)
    return (0.5 + 0.5 * nx / length, 0.5 + 0.5 * ny / length, 0.5 + 0.5 * nz / length, 1.0)


def normal_mapped_box(folder):
    bpy.ops.mesh.primitive_cube_add(size=2)
    obj = bpy.context.active_object
    mat, bsdf = principled("box", Roughness=0.35)
    colour = texture_node(mat, image("box_checker", folder, 256, lambda u, v: checker(u, v, 16)))
    normals = texture_node(mat, image("box_normal", folder, 256, bumps_normal), non_color=True)
    normal_map = mat.node_tree.nodes.new("ShaderNodeNormalMap")
    links = mat.node_tree.links
    links.new(colour.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(normals.outputs["Color"], normal_map.inputs["Color"])
    links.new(normal_map.outputs["Normal"], bsdf.inputs["Normal"])
    assign(obj, mat)


def emissive_panels(folder):
    """Three panels of strength 1, 4 and 12 (KHR_materials_emissive_strength) over a grey floor."""
    for i, (colour, strength) in enumerate((((1.0, 0.3, 0.2), 1.0), ((0.3, 1.0, 0.4), 4.0),
                                            ((0.3, 0.5, 1.0), 12.0))):
        bpy.ops.mesh.primitive_plane_add(size=1, location=(1.3 * (i - 1), 0, 0.6),
                                         rotation=(math.radians(90), 0, 0))
        mat, _ = principled(f"panel{i}", **{"Base Color": (0.02, 0.02, 0.02, 1.0),
                                             "Emission": (*colour, 1.0), "Emission Strength": strength})
        assign(bpy.context.active_object, mat)
    bpy.ops.mesh.primitive_plane_add(size=5, location=(0, 1.0, 0))
    mat, _ = principled("floor", **{"Base Color": (0.5, 0.5, 0.5, 1.0), "Roughness": 1.0})
    assign(bpy.context.active_object, mat)


def leaf_texel(u, v):
    """A leaf: an ellipse with a darker midrib; alpha 0 outside it."""
    x, y = 2 * u - 1, 2 * v - 1
    inside = (x / 0.45) ** 2 + y * y < 1
    rib = abs(x) < 0.03
    colour = (0.15, 0.35, 0.05) if rib else (0.25 + 0.2 * v, 0.6, 0.1)
    return (*colour, 1.0 if inside else 0.0)


def alpha_leaf(folder):
    bpy.ops.mesh.primitive_plane_add(size=2, rotation=(math.radians(70), 0, math.radians(20)))
    obj = bpy.context.active_object
    mat, bsdf = principled("leaf", Roughness=0.6)
    tex = texture_node(mat, image("leaf", folder, 256, leaf_texel))
    mat.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    mat.node_tree.links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
    mat.blend_method = "CLIP"
    mat.alpha_threshold = 0.5
    mat.use_backface_culling = False
    assign(obj, mat)


def gltf_settings_node(mat):
    """The exporter reads KHR_materials_volume's thickness from a node group named glTF Material Output."""
    group = bpy.data.node_groups.get("glTF Material Output")
    if group is None:
        group = bpy.data.node_groups.new("glTF Material Output", "ShaderNodeTree")
        group.inputs.new("NodeSocketFloat", "Occlusion")
        group.inputs.new("NodeSocketFloat", "Thickness")
    node = mat.node_tree.nodes.new("ShaderNodeGroup")
    node.node_tree = group
    return node


def glass_sphere(folder, roughness=0.0):
    """A solid glass ball of index 1.5 (KHR_materials_transmission, _ior, _volume with a faint tint)."""
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=1)
    obj = bpy.context.active_object
    smooth(obj)
    mat, _ = principled("glass", **{"Base Color": (1, 1, 1, 1), "Roughness": roughness, "Transmission": 1.0,
                                     "IOR": 1.5})
    settings = gltf_settings_node(mat)
    settings.inputs["Thickness"].default_value = 2.0
    absorption = mat.node_tree.nodes.new("ShaderNodeVolumeAbsorption")
    absorption.inputs["Color"].default_value = (0.75, 0.9, 1.0, 1.0)
    absorption.inputs["Density"].default_value = 0.5
    out = mat.node_tree.nodes["Material Output"]
    mat.node_tree.links.new(absorption.outputs["Volume"], out.inputs["Volume"])
    assign(obj, mat)


def frosted_glass_sphere(folder):
    """The glass ball with a roughness of 0.3: a rough interface (GGX refraction) on a volume."""
    glass_sphere(folder, roughness=0.3)


def clearcoat_sphere(folder):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=1)
    obj = bpy.context.active_object
    smooth(obj)
    mat, _ = principled("coated", **{"Base Color": (0.7, 0.04, 0.03, 1.0), "Roughness": 0.55,
                                      "Clearcoat": 1.0, "Clearcoat Roughness": 0.03})
    assign(obj, mat)


def vertex_colours(folder):
    """A sphere coloured per vertex by its position (COLOR_0 times a white base colour)."""
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=5, radius=1)
    obj = bpy.context.active_object
    smooth(obj)
    mesh = obj.data
    colours = mesh.color_attributes.new("Col", "FLOAT_COLOR", "POINT")
    for v in mesh.vertices:
        x, y, z = v.co
        colours.data[v.index].color = (0.5 + 0.45 * x, 0.5 + 0.45 * z, 0.5 - 0.45 * x * z, 1.0)
    mat, bsdf = principled("vertex_colour", Roughness=0.5)
    attribute = mat.node_tree.nodes.new("ShaderNodeVertexColor")
    attribute.layer_name = "Col"
    mat.node_tree.links.new(attribute.outputs["Color"], bsdf.inputs["Base Color"])
    assign(obj, mat)


MODELS = {
    "suzanne_textured": textured_suzanne,
    "sphere_grid": sphere_grid,
    "normal_mapped_box": normal_mapped_box,
    "emissive_panels": emissive_panels,
    "alpha_leaf": alpha_leaf,
    "glass_sphere": glass_sphere,
    "frosted_glass_sphere": frosted_glass_sphere,
    "clearcoat_sphere": clearcoat_sphere,
    "vertex_colours": vertex_colours,
}


def main():
    args = parse_args()
    os.makedirs(args.out, exist_ok=True)
    textures = os.path.join(args.out, "textures")
    os.makedirs(textures, exist_ok=True)
    for name, build in MODELS.items():
        empty_scene()
        build(textures)
        path = os.path.join(args.out, name + ".glb")
        export(path)
        print(f"built {path}", flush=True)


main()
