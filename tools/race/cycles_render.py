# Runs inside Blender (`blender -b --factory-startup --python tools/race/cycles_render.py -- ARGS`):
# renders a fragpath scene (an OBJ with Lambertian, glass, metal and emissive MTL materials, and a camera)
# with Cycles on the CPU, as tools/race_cycles.py asks, and writes the linear image as a PFM (rows bottom
# first).
#
# Matched to fragpath: Lambertian surfaces (Diffuse BSDF, roughness 0; map_Kd as an sRGB image, bilinear,
# repeated, times Kd), glass (illum 4/6/7/9 or Tf: Glass
# BSDF with Ni and Pr), metals (Pm: Principled, metallic, GGX, roughness Pr), emitters that emit from their
# front face only (a counter-clockwise face, as fragpath's), the OBJ's vertex normals where a face gives
# them and the flat face normal where it does not (Blender's C++ OBJ importer, wm.obj_import; the legacy
# import_scene.obj gave every face without normals the file's first `vn`), a pinhole camera with the
# vertical field of view, a 1-pixel box filter, the same bounce limit for every kind of bounce, no
# adaptive sampling, no denoising, no clamping, a fixed thread count.
#   ARGS: OBJ PFM_OUT WIDTH HEIGHT SPP MAX_DEPTH THREADS SEED EYE(x,y,z) TARGET UP FOV_DEGREES
# (MAX_DEPTH as fragpath counts it: 0 emitters only, 1 direct light)
import math
import os
import struct
import sys

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index("--") + 1:]
obj_path, out_path = args[0], args[1]
width, height, spp, depth, threads, seed = (int(a) for a in args[2:8])
eye, target, up = (Vector([float(v) for v in a.split(",")]) for a in args[8:11])
fov = float(args[11])


def to_blender(v):
    # fragpath's y-up OBJ, imported with forward -Z and up Y: (x, y, z) -> (x, -z, y).
    return Vector((v.x, -v.z, v.y))


def read_mtl(path):
    materials, current = {}, None
    for line in open(path):
        words = line.split()
        if not words:
            continue
        if words[0] == "newmtl":
            current = materials.setdefault(words[1], {"Ke": (0.0, 0.0, 0.0)})
        elif current is not None and words[0] in ("Kd", "Ke", "Tf"):
            values = [float(w) for w in words[1:4]]
            current[words[0]] = tuple(values + values[:1] * (3 - len(values)))
        elif current is not None and words[0] in ("Ni", "Pr", "Pm", "illum"):
            current[words[0]] = float(words[1])
        elif current is not None and words[0] == "map_Kd":
            current["map_Kd"] = os.path.join(os.path.dirname(path), words[-1])
    for values in materials.values():
        # fragpath's reading of Kd (src/scene/mtl_parse.cpp): 1 when a map_Kd stands alone, else 0.
        values.setdefault("Kd", (1.0, 1.0, 1.0) if "map_Kd" in values else (0.0, 0.0, 0.0))
    return materials


def linear_image(path):
    # The texels decoded from sRGB into a float image before Cycles filters them, as fragpath (and GPUs)
    # do: Cycles filters an 8-bit sRGB image first and decodes after, which darkens a magnified checker's
    # edges (the textured floor came out 2.8 % darker).
    encoded = bpy.data.images.load(path)
    encoded.colorspace_settings.name = "Non-Color"  # the raw texel values, not decoded
    width, height = encoded.size
    raw = list(encoded.pixels)
    decode = lambda c: c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    linear = [decode(v) if i % 4 != 3 else v for i, v in enumerate(raw)]
    image = bpy.data.images.new(os.path.basename(path) + ".linear", width, height, alpha=True, float_buffer=True)
    image.colorspace_settings.name = "Linear"
    image.pixels = linear
    return image


bpy.ops.wm.read_factory_settings(use_empty=True)
# Not the legacy import_scene.obj: it sets the normal of every corner the file gives none to the file's
# first `vn` (any object's), where fragpath (and this importer: a zero custom normal) uses the face's.
# It makes one object per `o` statement (3.4 has no option for it); rendering does not depend on that.
bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="NEGATIVE_Z", up_axis="Y")
mtl = {}
for line in open(obj_path):
    if line.startswith("mtllib"):
        mtl.update(read_mtl(os.path.join(os.path.dirname(obj_path), line.split(None, 1)[1].strip())))

for material in bpy.data.materials:
    values = mtl.get(material.name, {"Kd": (0.8, 0.8, 0.8), "Ke": (0.0, 0.0, 0.0)})
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    roughness = values.get("Pr", 0.0)  # fragpath's GGX alpha is roughness^2, as Cycles'
    if values.get("illum") in (4.0, 6.0, 7.0, 9.0) or max(values.get("Tf", (0.0,))) > 0.0:
        # Glass (fragpath's dielectric: exact Fresnel, sharp below roughness 0.01).
        diffuse = nodes.new("ShaderNodeBsdfGlass")
        diffuse.distribution = "SHARP" if roughness < 0.01 else "GGX"
        diffuse.inputs["Color"].default_value = (*values.get("Tf", (1.0, 1.0, 1.0)), 1.0)
        diffuse.inputs["Roughness"].default_value = roughness
        diffuse.inputs["IOR"].default_value = values.get("Ni", 1.5)
    elif values.get("Pm", 0.0) > 0.0:
        # Metal: GGX with Schlick's Fresnel from the base colour (fragpath's conductor).
        diffuse = nodes.new("ShaderNodeBsdfPrincipled")
        diffuse.distribution = "GGX"
        diffuse.inputs["Base Color"].default_value = (*values["Kd"], 1.0)
        diffuse.inputs["Metallic"].default_value = 1.0
        diffuse.inputs["Roughness"].default_value = roughness
    else:
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (*values["Kd"], 1.0)
        diffuse.inputs["Roughness"].default_value = 0.0
        if "map_Kd" in values:
            # The texture times Kd: sRGB texels, bilinear, repeat, the OBJ's texture coordinates (as
            # fragpath's sampleTexture, glsl/common/textures.glsl).
            texture = nodes.new("ShaderNodeTexImage")
            texture.image = linear_image(values["map_Kd"])
            texture.interpolation = "Linear"
            texture.extension = "REPEAT"
            multiply = nodes.new("ShaderNodeMixRGB")
            multiply.blend_type = "MULTIPLY"
            multiply.inputs["Fac"].default_value = 1.0
            links.new(texture.outputs["Color"], multiply.inputs["Color1"])
            multiply.inputs["Color2"].default_value = (*values["Kd"], 1.0)
            links.new(multiply.outputs["Color"], diffuse.inputs["Color"])
    shader = diffuse.outputs[0]
    if max(values["Ke"]) > 0.0:
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*values["Ke"], 1.0)
        emission.inputs["Strength"].default_value = 1.0
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs[0], add.inputs[0])
        links.new(emission.outputs["Emission"], add.inputs[1])
        # One-sided, as fragpath's emitters: the back face only reflects.
        geometry = nodes.new("ShaderNodeNewGeometry")
        mix = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        links.new(add.outputs["Shader"], mix.inputs[1])
        links.new(diffuse.outputs[0], mix.inputs[2])
        shader = mix.outputs["Shader"]
    links.new(shader, output.inputs["Surface"])

scene = bpy.context.scene
world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(fov)
camera_data.clip_start = 1e-3 * (to_blender(target) - to_blender(eye)).length
camera_data.clip_end = 1e6
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
camera.location = to_blender(eye)
direction = to_blender(target) - to_blender(eye)
camera.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
scene.camera = camera

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = spp
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.seed = seed
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
# Cycles counts bounces after the first: its 0 is fragpath's depth 1 (direct light).
bounces = max(depth - 1, 0)
scene.cycles.max_bounces = bounces
scene.cycles.diffuse_bounces = bounces
scene.cycles.glossy_bounces = bounces
scene.cycles.transmission_bounces = bounces
scene.cycles.transparent_max_bounces = bounces
scene.cycles.sample_clamp_direct = 0.0
scene.cycles.sample_clamp_indirect = 0.0
scene.cycles.caustics_reflective = True
scene.cycles.caustics_refractive = True
scene.cycles.blur_glossy = 0.0
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
exr = out_path + ".exr"
scene.render.filepath = exr
bpy.ops.render.render(write_still=True)

image = bpy.data.images.load(exr)
pixels = list(image.pixels)  # RGBA, rows bottom first: PFM's order
with open(out_path, "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
    rgb = [pixels[i + c] for i in range(0, len(pixels), 4) for c in range(3)]
    f.write(struct.pack("<%df" % len(rgb), *rgb))
