#pragma once
// Scenes made by code rather than read from files: test objects with known answers, and benchmark
// meshes with exact triangle counts.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "image/image_stats.h"
#include "scene/scene.h"

namespace fp {

// Appends a UV sphere of 2 * segments * (rings - 1) triangles, wound counter-clockwise seen from
// outside; `smooth` gives vertex normals (the sphere's own), otherwise the flat facet normals.
void appendSphere(Scene& scene, const glm::vec3& center, float radius, int rings, int segments,
                  uint32_t material, bool smooth);

// Appends the quad a b c d (two triangles, flat normals), its front face the side from which a b c d
// run counter-clockwise.
void appendQuad(Scene& scene, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                uint32_t material);

// A caustic, for bidirectional path tracing: a 0.2 x 0.2 one-sided emitter (radiance 100) facing down
// 3 units above a diffuse floor (albedo 0.6, 6 x 6), and a smooth-shaded glass sphere (ior 1.5, GGX
// roughness `glassRoughness`, radius 0.5, 24 rings x 48 segments) between them, centre 0.9 above the
// floor; the camera looks down at the floor under the sphere, where its shadow and caustic fall.
Scene causticScene(float glassRoughness);
// That floor in a 24 x 24 image of causticScene's camera.
constexpr PixelRect kCausticUnderSphere{6, 13, 12, 6};

// Light from an environment map alone, for the noise study: a 10 x 10 diffuse ground (albedo 0.6) and
// three smooth UV spheres on it (radii 1, 0.6, 0.8; 24 rings x 48 segments; 6,626 triangles in all)
// under a 256 x 128 equirectangular sky made in code: a blue gradient above the horizon, brown ground
// below, and a 4 x 4-texel sun of radiance (400, 300, 200) about 59 degrees up, which casts sharp
// shadows and whose small solid angle makes the sky's importance sampling matter. The scene of
// tools/make_env_scene.py (docs/optimisation-log.md, entry 31), built without files.
Scene environmentLitScene();

// The benchmark scenes below all stand in one lit room, so that their figures differ only by what is in
// it: a 2 x 2 x 2 box open towards -z (where the camera looks in from, as for the Cornell box), a
// white floor, ceiling and back wall, a red wall on the image's left and a green one on its right, and a
// one-sided emitter just below the ceiling, facing down. Walls, ceiling and emitter are 10 triangles; the
// floor is 2 or more.
constexpr int kRoomTriangles = 10;  // without the floor

// How benchmarkSphereScene spends its triangles: sphereTriangles = 2 * segments * (rings - 1), and the
// floor is split into strips to take up the rest, so that the total is exact.
struct SphereSceneLayout {
    int rings = 0, segments = 0;
    int sphereTriangles = 0, floorTriangles = 0;
};
constexpr int kMinSphereSceneTriangles = kRoomTriangles + 2 + 6;  // the smallest sphere: 3 segments, 2 rings
// Throws fp::Error when `triangles` is below kMinSphereSceneTriangles.
SphereSceneLayout sphereSceneLayout(int triangles);

// A smooth-shaded UV sphere just above the floor of the lit room, with exactly `triangles` triangles in
// all. The sphere takes as many as it can with segments between 1 and 4 times (rings - 1), so that its
// quads are not slivers; the floor takes the few left (2 of 1,000, 16 of 100,000, 6 of 1,000,000).
Scene benchmarkSphereScene(int triangles);

// The worst case for a BVH: exactly `triangles` triangles in all, the lit room with a one-quad floor
// and triangles - 12 random ones filling its middle. Each has random vertices within 0.12 of a random
// centre, so their bounds overlap heavily and no split separates them well. The same seed gives the
// same scene on every machine (the generator is our own, not a standard library distribution).
constexpr int kMinSoupTriangles = kRoomTriangles + 2 + 1;
Scene randomTriangleSoup(int triangles, uint32_t seed);

// A mesh given as shared vertex positions and triangles indexing them.
struct IndexedMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::array<uint32_t, 3>> cells;
};

// Reads a mesh as the npm mesh packages ship it (the `bunny` package, for one): a CommonJS module
// `exports.positions=[[x,y,z],...]` and `exports.cells=[[i,j,k],...]`, or a JSON object with the keys
// "positions" and "cells". Only those two arrays are read; the module is never run. Throws fp::Error
// naming `name` for anything else, or an index out of range.
IndexedMesh parseMeshModule(const std::string& text, const std::string& name);

// The mesh (y up) standing on the middle of the floor of the lit room, its largest side scaled to 0.6 of
// the room's: the room with a one-quad floor plus one triangle per cell, except cells of zero area,
// which are dropped. Throws fp::Error for a mesh without a triangle of non-zero area.
Scene benchmarkMeshScene(const IndexedMesh& mesh, const std::string& name);

}  // namespace fp
