"""Writing the race's generated scenes (tools/make_window_room.py, make_mesh_room.py, make_race_gltf.py,
make_lamp_plane.py): OBJ/MTL, Radiance .hdr skies and scene files, standard library only."""
import json
import math
import os


def rgbe(r, g, b):
    """One Radiance RGBE texel (Ward, Graphics Gems II, "Real Pixels"): a shared exponent."""
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes((min(255, int(r * s)), min(255, int(g * s)), min(255, int(b * s)), e + 128))


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


def write_sky(path, width, height, sun, sun_radiance, sun_texels=2):
    """An equirectangular sky: blue above the horizon, brighter towards it, a brown ground below, and a
    sun of `sun_texels` x `sun_texels` texels of radiance `sun_radiance` (RGB) centred on direction
    `sun`. Written as an uncompressed .hdr (scanlines top first, as `-Y H +X W` says)."""
    su, sv = texel_of_direction(sun)
    sx, sy = int(su * width) - sun_texels // 2, int(sv * height) - sun_texels // 2
    out = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
    for y in range(height):
        for x in range(width):
            if sx <= x < sx + sun_texels and sy <= y < sy + sun_texels:
                out += rgbe(*sun_radiance)
                continue
            d = direction_of_texel((x + 0.5) / width, (y + 0.5) / height)
            if d[1] > 0:
                horizon = 1 - d[1]
                r, g, b = 0.25 + 0.55 * horizon ** 3, 0.4 + 0.45 * horizon ** 3, 0.9 + 0.1 * horizon ** 3
            else:
                r, g, b = 0.2, 0.16, 0.12
            out += rgbe(r, g, b)
    with open(path, "wb") as f:
        f.write(out)


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
