"""Writing the race's generated scenes (tools/make_window_room.py, make_mesh_room.py, make_race_gltf.py,
make_lamp_plane.py): OBJ/MTL, Radiance .hdr skies and scene files, standard library only."""
import json
import math
import os
import struct
import sys


def output_folder(doc, add_arguments=None):
    """A scene generator's command line: --out FOLDER (created) and whatever add_arguments(parser) adds;
    the description is the first line of the generator's docstring `doc`."""
    import argparse
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--out", required=True)
    if add_arguments:
        add_arguments(parser)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    return args


def direction_of_texel(u, v):
    """fragpath's uvToDirection (glsl/common/lights.glsl) without rotation: v = 0 is +y (the file's first
    scanline), u = 0.5 looks along -z."""
    phi, theta = (u - 0.5) * 2 * math.pi, v * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def texel_of_direction(d):
    """fragpath's directionToUv: (u, v) of a unit direction."""
    return 0.5 + math.atan2(d[0], -d[2]) / (2 * math.pi), math.acos(max(-1.0, min(1.0, d[1]))) / math.pi


def sun_direction(elevation_degrees, azimuth_degrees):
    """A unit direction towards the sun: azimuth 0 is +z, 90 is +x."""
    e, a = math.radians(elevation_degrees), math.radians(azimuth_degrees)
    return (math.sin(a) * math.cos(e), math.sin(e), math.cos(a) * math.cos(e))


def write_exr(path, width, height, texel):
    """An uncompressed scanline OpenEXR of 32-bit float R, G, B (OpenEXR file layout: magic, version,
    header attributes, line offset table, one scanline per block; channels in alphabetical order).
    texel(x, y) gives (r, g, b), y = 0 the top row. EXR, not Radiance .hdr: the renderers' .hdr readers
    round RGBE differently (Blender's adds half a mantissa step, fragpath's stb_image none), which would
    make Cycles' sky 0.2-0.4 % brighter."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    channels = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attribute("channels", "chlist", channels) +
              attribute("compression", "compression", b"\0") + attribute("dataWindow", "box2i", window) +
              attribute("displayWindow", "box2i", window) + attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line_size = 8 + 12 * width
    first = len(header) + 8 * height
    offsets = struct.pack("<%dQ" % height, *(first + y * line_size for y in range(height)))
    with open(path, "wb") as f:
        f.write(header + offsets)
        for y in range(height):
            row = [texel(x, y) for x in range(width)]
            f.write(struct.pack("<ii", y, 12 * width))
            for c in (2, 1, 0):
                f.write(struct.pack("<%df" % width, *(t[c] for t in row)))


def sky(width, height, sun, sun_radiance, sun_texels=2):
    """texel(x, y) of an equirectangular sky (y = 0 the top row): blue above the horizon, brighter
    towards it, a brown ground below, and a sun of `sun_texels` x `sun_texels` texels of radiance
    `sun_radiance` (RGB) centred on direction `sun`."""
    su, sv = texel_of_direction(sun)
    sx, sy = int(su * width) - sun_texels // 2, int(sv * height) - sun_texels // 2

    def texel(x, y):
        if sx <= x < sx + sun_texels and sy <= y < sy + sun_texels:
            return tuple(sun_radiance)
        d = direction_of_texel((x + 0.5) / width, (y + 0.5) / height)
        if d[1] <= 0:
            return (0.2, 0.16, 0.12)
        horizon = (1 - d[1]) ** 3
        return (0.25 + 0.55 * horizon, 0.4 + 0.45 * horizon, 0.9 + 0.1 * horizon)

    return texel


def write_sky(path, width, height, sun, sun_radiance, sun_texels=2):
    """sky(...) written as an .exr (write_exr)."""
    write_exr(path, width, height, sky(width, height, sun, sun_radiance, sun_texels))


def irradiance_from_above(width, height, texel):
    """RGB irradiance on an upward-facing surface under an equirectangular map of an even height,
    radiance constant over each texel: the sum of radiance x the texel's cosine-weighted solid angle,
    (2 pi / width) x (sin^2 theta1 - sin^2 theta0) / 2 for its rows' polar angles theta0, theta1."""
    total = [0.0, 0.0, 0.0]
    for y in range(height // 2):
        t0, t1 = math.pi * y / height, math.pi * (y + 1) / height
        weight = 2 * math.pi / width * (math.sin(t1) ** 2 - math.sin(t0) ** 2) / 2
        for x in range(width):
            for c, value in enumerate(texel(x, y)):
                total[c] += value * weight
    return total


class Obj:
    """Triangles grouped by material; quads are written as two triangles, counter-clockwise (the face's
    front, the side an emitter lights) as seen from where the normal points."""

    def __init__(self):
        self.vertices, self.faces = [], []  # faces: (material, (i, j, k)) with 1-based indices

    def vertex(self, p):
        self.vertices.append(tuple(p))
        return len(self.vertices)

    def triangle(self, material, a, b, c):
        self.faces.append((material, (a, b, c)))

    def quad(self, material, corners):
        i = [self.vertex(p) for p in corners]
        self.triangle(material, i[0], i[1], i[2])
        self.triangle(material, i[0], i[2], i[3])

    def write(self, folder, name, materials):
        """name.obj and name.mtl; materials: {name: {"Kd": (r, g, b), "Ke": ...}} in MTL's keys."""
        with open(os.path.join(folder, name + ".mtl"), "w") as f:
            for material, keys in materials.items():
                f.write("newmtl %s\n" % material)
                for key, value in keys.items():
                    f.write("%s %s\n" % (key, " ".join("%g" % x for x in value)))
        with open(os.path.join(folder, name + ".obj"), "w") as f:
            f.write("mtllib %s.mtl\n" % name)
            for p in self.vertices:
                f.write("v %.6g %.6g %.6g\n" % p)
            current = None
            for material, (a, b, c) in sorted(self.faces, key=lambda face: face[0]):
                if material != current:
                    f.write("usemtl %s\n" % material)
                    current = material
                f.write("f %d %d %d\n" % (a, b, c))


def box_quads(lo, hi):
    """The six outward-facing quads of an axis-aligned box, each counter-clockwise seen from outside."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [
        [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],  # top (+y)
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],  # bottom (-y)
        [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],  # -z
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # +z
        [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],  # -x
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],  # +x
    ]


def write_scene(folder, scene):
    with open(os.path.join(folder, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def write_png(path, width, height, rgb, exposure=1.0):
    """A linear RGB image (rows bottom first, as PFM) as an sRGB PNG, clamped, for looking at."""
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from make_gltf_showcase import png

    def encode(c):
        c = max(0.0, min(1.0, c * exposure))
        return int(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055) + 0.5)

    rows = [[encode(rgb[3 * (y * width + x) + c]) for x in range(width) for c in range(3)]
            for y in reversed(range(height))]
    with open(path, "wb") as f:
        f.write(png(width, height, rows, 3))
