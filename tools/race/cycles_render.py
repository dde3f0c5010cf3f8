# Runs inside Blender (`blender -b --factory-startup --python tools/race/cycles_render.py -- JOB.json`):
# renders a fragpath scene file with Cycles on the CPU, as tools/race_cycles.py asks, and writes the
# linear image as a PFM (rows bottom first).
#
# JOB.json: {"scene": fragpath scene file (.json with "mesh", "camera", optional "environment"), "out":
# PFM path, "width", "height", "spp", "max_depth" (as fragpath counts it: 0 emitters only, 1 direct
# light), "threads", "seed"}. Scene files with "lights" (punctual lights) are refused: Blender's units
# for them differ and the race does not need them.
#
# Matched to fragpath:
# - OBJ meshes (Blender's C++ importer, wm.obj_import: the legacy import_scene.obj gave every face
#   without normals the file's first `vn`): Lambertian surfaces (Diffuse BSDF, roughness 0; map_Kd as an
#   sRGB image decoded before filtering, bilinear, repeated, times Kd), glass (illum 4/6/7/9 or Tf: Glass
#   BSDF with Ni and Pr), metals (Pm: Principled, metallic, GGX, roughness Pr), emitters that emit from
#   their front face only (a counter-clockwise face, as fragpath's).
# - glTF meshes (Blender's bundled importer, io_scene_gltf2, which needs Debian's python3-numpy): each
#   imported Principled BSDF is rebuilt as fragpath's glTF model (glsl/common/bsdf.glsl,
#   "metallic-roughness") as far as Cycles' nodes can: metallic 1 is the Principled conductor (GGX, F0 =
#   base colour); metallic 0 is Principled's specular layer alone (black base: GGX with the exact
#   Fresnel of index 1.5 at the microfacet normal, as fragpath's coat) plus a Diffuse base times
#   1 - F(wo) (Fresnel node). fragpath's base has a second factor, 1 - F(wi) on the light's side, which
#   no Cycles node can see: 1 - F_dr = 0.908 (the cosine-weighted mean of 1 - F at index 1.5) stands for
#   it, exact under uniform light; under a sun 50 degrees from the normal (1 - F = 0.94) Cycles' base is
#   3 % darker (the race's glTF scene: Cycles 1.8 % darker over the image; race it against each
#   renderer's own reference). Base colour textures are decoded from sRGB before filtering.
# - The environment: a constant colour, or an equirectangular map looked up as fragpath's
#   directionToUv (glsl/common/lights.glsl: u = 0.5 + atan2(x, -z) / 2 pi with +y up, turned by
#   "rotation" degrees about +y; the nearest texel, no filtering) times "intensity" (which a constant
#   colour ignores, as in fragpath).
# - A pinhole camera with the vertical field of view, a 1-pixel box filter, the same bounce limit for
#   every kind of bounce, no adaptive sampling, no denoising, no clamping, a fixed thread count.
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Matrix, Vector

job = json.load(open(sys.argv[sys.argv.index("--") + 1]))
scene_path = os.path.abspath(job["scene"])
scene_file = json.load(open(scene_path))
scene_dir = os.path.dirname(scene_path)
mesh_path = os.path.join(scene_dir, scene_file["mesh"])
width, height, spp, depth = job["width"], job["height"], job["spp"], job["max_depth"]
if scene_file.get("lights"):
    raise SystemExit("cycles_render.py: scene files with punctual \"lights\" are not matched")
if "camera" not in scene_file:
    raise SystemExit("cycles_render.py: %s has no \"camera\": the race matches only the scene file's camera"
                     % scene_path)
cam = scene_file["camera"]


def to_blender(v):
    # fragpath's y-up world, as both importers map it (OBJ forward -Z up Y; glTF's +Y up): (x, y, z) ->
    # (x, -z, y).
    return Vector((v[0], -v[2], v[1]))


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


def linear_image(encoded):
    # The texels decoded from sRGB into a float image before Cycles filters them, as fragpath (and GPUs)
    # do: Cycles filters an 8-bit sRGB image first and decodes after, which darkens a magnified checker's
    # edges (the textured floor came out 2.8 % darker).
    encoded.colorspace_settings.name = "Non-Color"  # the raw texel values, not decoded
    w, h = encoded.size
    raw = list(encoded.pixels)
    decode = lambda c: c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    linear = [decode(v) if i % 4 != 3 else v for i, v in enumerate(raw)]
    image = bpy.data.images.new(encoded.name + ".linear", w, h, alpha=True, float_buffer=True)
    image.colorspace_settings.name = "Linear"
    image.pixels = linear
    return image


def one_sided_emission(nodes, links, surface, colour_socket=None, colour=None):
    """surface + emission on the front face only (fragpath's emitters), the back face only reflecting."""
    emission = nodes.new("ShaderNodeEmission")
    if colour_socket is not None:
        links.new(colour_socket, emission.inputs["Color"])
    else:
        emission.inputs["Color"].default_value = (*colour, 1.0)
    emission.inputs["Strength"].default_value = 1.0
    add = nodes.new("ShaderNodeAddShader")
    links.new(surface, add.inputs[0])
    links.new(emission.outputs["Emission"], add.inputs[1])
    geometry = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(add.outputs["Shader"], mix.inputs[1])
    links.new(surface, mix.inputs[2])
    return mix.outputs["Shader"]


def obj_materials():
    # Not the legacy import_scene.obj: it sets the normal of every corner the file gives none to the
    # file's first `vn` (any object's), where fragpath (and this importer: a zero custom normal) uses the
    # face's. It makes one object per `o` statement; rendering does not depend on that.
    bpy.ops.wm.obj_import(filepath=mesh_path, forward_axis="NEGATIVE_Z", up_axis="Y")
    mtl = {}
    for line in open(mesh_path):
        if line.startswith("mtllib"):
            mtl.update(read_mtl(os.path.join(os.path.dirname(mesh_path), line.split(None, 1)[1].strip())))
    for material in bpy.data.materials:
        values = mtl.get(material.name, {"Kd": (0.8, 0.8, 0.8), "Ke": (0.0, 0.0, 0.0)})
        material.use_nodes = True
        nodes, links = material.node_tree.nodes, material.node_tree.links
        nodes.clear()
        output = nodes.new("ShaderNodeOutputMaterial")
        roughness = values.get("Pr", 0.0)  # fragpath's GGX alpha is roughness^2, as Cycles'
        if values.get("illum") in (4.0, 6.0, 7.0, 9.0) or max(values.get("Tf", (0.0,))) > 0.0:
            # Glass (fragpath's dielectric: exact Fresnel, sharp below roughness 0.01).
            bsdf = nodes.new("ShaderNodeBsdfGlass")
            bsdf.distribution = "SHARP" if roughness < 0.01 else "GGX"
            bsdf.inputs["Color"].default_value = (*values.get("Tf", (1.0, 1.0, 1.0)), 1.0)
            bsdf.inputs["Roughness"].default_value = roughness
            bsdf.inputs["IOR"].default_value = values.get("Ni", 1.5)
        elif values.get("Pm", 0.0) > 0.0:
            # Metal: GGX with Schlick's Fresnel from the base colour (fragpath's conductor).
            bsdf = nodes.new("ShaderNodeBsdfPrincipled")
            bsdf.distribution = "GGX"
            bsdf.inputs["Base Color"].default_value = (*values["Kd"], 1.0)
            bsdf.inputs["Metallic"].default_value = 1.0
            bsdf.inputs["Roughness"].default_value = roughness
        else:
            bsdf = nodes.new("ShaderNodeBsdfDiffuse")
            bsdf.inputs["Color"].default_value = (*values["Kd"], 1.0)
            bsdf.inputs["Roughness"].default_value = 0.0
            if "map_Kd" in values:
                # The texture times Kd: sRGB texels, bilinear, repeat, the OBJ's texture coordinates (as
                # fragpath's sampleTexture, glsl/common/textures.glsl).
                texture = nodes.new("ShaderNodeTexImage")
                texture.image = linear_image(bpy.data.images.load(values["map_Kd"]))
                texture.interpolation = "Linear"
                texture.extension = "REPEAT"
                multiply = nodes.new("ShaderNodeMixRGB")
                multiply.blend_type = "MULTIPLY"
                multiply.inputs["Fac"].default_value = 1.0
                links.new(texture.outputs["Color"], multiply.inputs["Color1"])
                multiply.inputs["Color2"].default_value = (*values["Kd"], 1.0)
                links.new(multiply.outputs["Color"], bsdf.inputs["Color"])
        shader = bsdf.outputs[0]
        if max(values["Ke"]) > 0.0:
            shader = one_sided_emission(nodes, links, shader, colour=values["Ke"])
        links.new(shader, output.inputs["Surface"])


# 1 - F_dr: the cosine-weighted hemispherical mean of 1 - F(cos) for a dielectric of index 1.5 (exact
# Fresnel), the share of diffuse light a smooth coat lets through on the light's side (computed below).
def coat_transmittance(ior, steps=4096):
    def fresnel(c):
        s2 = max(0.0, 1.0 - c * c) / (ior * ior)
        if s2 >= 1.0:
            return 1.0
        t = math.sqrt(1.0 - s2)
        rs = (c - ior * t) / (c + ior * t)
        rp = (ior * c - t) / (ior * c + t)
        return 0.5 * (rs * rs + rp * rp)

    # integral of (1 - F(mu)) 2 mu dmu over [0, 1], midpoint rule
    return sum((1.0 - fresnel((i + 0.5) / steps)) * 2.0 * (i + 0.5) / steps for i in range(steps)) / steps


def gltf_materials():
    # The importer needs numpy (Debian's python3-numpy). Blender's embedded Python finds its home from
    # the PATH, and a python3 of pyenv's or a virtualenv's ahead of Debian's hides Debian's packages.
    if "/usr/lib/python3/dist-packages" not in sys.path:
        sys.path.append("/usr/lib/python3/dist-packages")
    import numpy
    if "bool" not in vars(numpy):
        # Blender 3.4's importer uses numpy.bool, the alias of bool that numpy 1.24 (Debian 12's) removed.
        numpy.bool = bool
    bpy.ops.import_scene.gltf(filepath=mesh_path)
    for obj in list(bpy.data.objects):
        if obj.type in ("LIGHT", "CAMERA"):
            if obj.type == "LIGHT":
                raise SystemExit("cycles_render.py: glTF punctual lights are not matched")
            bpy.data.objects.remove(obj)
    coat = coat_transmittance(1.5)
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        nodes, links = material.node_tree.nodes, material.node_tree.links
        principled = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
        output = next((n for n in nodes if n.type == "OUTPUT_MATERIAL"), None)
        if principled is None or output is None:
            continue
        for node in nodes:
            if node.type == "TEX_IMAGE" and node.image and node.image.colorspace_settings.name == "sRGB":
                node.image = linear_image(node.image)

        def source(name):
            socket = principled.inputs[name]
            return socket.links[0].from_socket if socket.links else None

        base_link, base = source("Base Color"), principled.inputs["Base Color"].default_value
        metallic = principled.inputs["Metallic"].default_value
        roughness = principled.inputs["Roughness"].default_value
        if source("Metallic") or source("Roughness") or source("Normal") or source("Alpha"):
            raise SystemExit("cycles_render.py: %s: metallic/roughness, normal and alpha maps are not matched"
                             % material.name)
        if metallic >= 1.0:
            principled.distribution = "GGX"
            shader = principled.outputs[0]
        elif metallic <= 0.0:
            # The coat: Principled v1's specular layer alone (black base, specular 0.5: F0 = 0.04, which
            # its Fresnel turns into the exact dielectric Fresnel of index 1.5 at the microfacet normal,
            # as fragpath's coat). The base: Lambertian, times 1 - F(wo) (Fresnel node, the shading
            # normal) and 1 - F_dr in place of fragpath's 1 - F(wi).
            principled.distribution = "GGX"
            if base_link:
                links.remove(principled.inputs["Base Color"].links[0])
            principled.inputs["Base Color"].default_value = (0.0, 0.0, 0.0, 1.0)
            principled.inputs["Specular"].default_value = 0.5
            principled.inputs["Specular Tint"].default_value = 0.0
            principled.inputs["Sheen"].default_value = 0.0
            principled.inputs["Subsurface"].default_value = 0.0
            fresnel = nodes.new("ShaderNodeFresnel")
            fresnel.inputs["IOR"].default_value = 1.5
            through = nodes.new("ShaderNodeMath")
            through.operation = "MULTIPLY_ADD"  # (F x -coat) + coat = coat (1 - F)
            links.new(fresnel.outputs["Fac"], through.inputs[0])
            through.inputs[1].default_value = -coat
            through.inputs[2].default_value = coat
            scale = nodes.new("ShaderNodeMixRGB")
            scale.blend_type = "MULTIPLY"
            scale.inputs["Fac"].default_value = 1.0
            if base_link:
                links.new(base_link, scale.inputs["Color1"])
            else:
                scale.inputs["Color1"].default_value = base
            links.new(through.outputs["Value"], scale.inputs["Color2"])
            diffuse = nodes.new("ShaderNodeBsdfDiffuse")
            diffuse.inputs["Roughness"].default_value = 0.0
            links.new(scale.outputs["Color"], diffuse.inputs["Color"])
            add = nodes.new("ShaderNodeAddShader")
            links.new(principled.outputs[0], add.inputs[0])
            links.new(diffuse.outputs[0], add.inputs[1])
            shader = add.outputs["Shader"]
        else:
            raise SystemExit("cycles_render.py: %s: metallic %g between 0 and 1 is not matched" %
                             (material.name, metallic))
        emission_strength = principled.inputs["Emission Strength"].default_value
        emission = principled.inputs["Emission"].default_value
        if source("Emission") or (emission_strength > 0.0 and max(emission[:3]) > 0.0):
            raise SystemExit("cycles_render.py: %s: glTF emission is not matched" % material.name)
        links.new(shader, output.inputs["Surface"])


def world_from(environment):
    world = bpy.data.worlds.new("environment")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    background = nodes["Background"]
    if environment is None:
        background.inputs["Strength"].default_value = 0.0
        return world
    if "color" in environment:
        # fragpath's intensity scales a map only (src/render/renderer.cpp, environmentColor_).
        background.inputs["Strength"].default_value = 1.0
        background.inputs["Color"].default_value = (*environment["color"], 1.0)
        return world
    background.inputs["Strength"].default_value = float(environment.get("intensity", 1.0))
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(os.path.join(scene_dir, environment["map"]))
    texture.image.colorspace_settings.name = "Linear"
    texture.interpolation = "Closest"  # fragpath reads the nearest texel
    texture.projection = "EQUIRECTANGULAR"
    # Cycles' equirectangular u is 0.5 - atan2(Y, X) / 2 pi in Blender's z-up frame, X = x, Y = -z;
    # fragpath's u is 0.5 + atan2(x, -z) / 2 pi = Cycles' u + 1/4, that is Cycles' lookup of the
    # direction turned by -90 degrees about Blender's Z. fragpath turns the direction by -rotation about
    # +y before the lookup, which is -rotation about Blender's Z. (v: both put +y at the image's top row.)
    coordinates = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "VECTOR"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, -math.pi / 2 - math.radians(
        float(environment.get("rotation", 0.0))))
    links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], background.inputs["Color"])
    return world


bpy.ops.wm.read_factory_settings(use_empty=True)
if mesh_path.lower().endswith((".gltf", ".glb")):
    gltf_materials()
else:
    obj_materials()

scene = bpy.context.scene
scene.world = world_from(scene_file.get("environment"))

eye, target = to_blender(cam["eye"]), to_blender(cam["target"])
camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(cam.get("fov", 40.0))
camera_data.clip_start = 1e-3 * (target - eye).length
camera_data.clip_end = 1e6
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
# Camera axes as fragpath's (src/scene/camera.cpp): right = forward x up, the image's up across the view;
# Blender's camera looks down its local -Z with local +Y up.
forward = (target - eye).normalized()
right = forward.cross(to_blender(cam.get("up", [0, 1, 0]))).normalized()
true_up = right.cross(forward)
rotation = Matrix((right, true_up, -forward)).transposed()  # columns: the local axes in the world
camera.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
scene.camera = camera

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = spp
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.seed = job["seed"]
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
scene.render.threads = job["threads"]
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
out_path = job["out"]
exr = out_path + ".exr"
scene.render.filepath = exr
bpy.ops.render.render(write_still=True)

image = bpy.data.images.load(exr)
pixels = list(image.pixels)  # RGBA, rows bottom first: PFM's order
with open(out_path, "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
    rgb = [pixels[i + c] for i in range(0, len(pixels), 4) for c in range(3)]
    f.write(struct.pack("<%df" % len(rgb), *rgb))
os.remove(exr)
