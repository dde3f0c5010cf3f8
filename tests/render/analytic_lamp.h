#pragma once
// A small square lamp just above a large diffuse floor, whose direct light has a closed form: the
// analytic case the native reference (tests/native) and the GPU integrators (tests/render) are checked
// against, at the origin, far from it and at very small and very large sizes (issue 15). The floor's
// radiance at a point is rho Le F, F the form factor from that point to the lamp.
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/accumulation.h"
#include "render/render_test_util.h"
#include "scene/scene.h"

namespace fp::test {

struct LampCase {
    std::string name;
    double side;    // a: the lamp is an a x a square, emitting down
    double height;  // h: above the floor
    double shiftX;  // the whole scene moved this far along x
    // Half the floor's width; 0: 10 a. The floor's radiance does not depend on it (nothing but the
    // black lamp is above it), but rays leave it 2^-18 of its triangles' largest coordinate above it
    // (glsl/common/ray_offset.glsl), and from a floor 20 a wide that lifts what they see of a lamp 0.5 a
    // above it by 0.02 % (issue 35).
    double floorHalf = 0.0;
    // The lamp as tiles x tiles squares (2 tiles^2 triangles), for the light tree to choose among.
    int tiles = 1;
};

// Near enough for the old offsets (1e-5 of the scene's reach, shadow rays shortened by 1e-4 of their
// length) to lose nearly every light sample, far enough from the coordinates' float spacing for any
// offset scheme: the translated lamp is 1000 wide so that 1e5 is far from the origin but a
// 2^-18 x 1e5 offset (0.4) is still small beside its height.
inline std::vector<LampCase> lampCases() {
    return {{"unit lamp at h = 0.2 a", 1.0, 0.2, 0.0},
            {"unit lamp at h = 0.02 a", 1.0, 0.02, 0.0},
            {"1 mm lamp", 1e-3, 2e-4, 0.0},
            {"10 km lamp", 1e4, 2e3, 0.0},
            {"lamp at x = 1e5", 1e3, 200.0, 1e5}};
}

constexpr float kLampFloorAlbedo[3] = {0.8f, 0.5f, 0.3f};
constexpr float kLampRadiance[3] = {1.0f, 2.0f, 4.0f};

inline void appendQuad(Scene& scene, const glm::vec3 (&c)[4], uint32_t material) {
    glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
    for (auto tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
        Triangle t;
        t.p = {c[tri[0]], c[tri[1]], c[tri[2]]};
        t.n = {n, n, n};
        t.material = material;
        scene.triangles.push_back(t);
    }
}

// The floor: a square 20 a wide (or 2 floorHalf) at y = 0, facing up; the lamp: centred h above the floor's
// centre, its front face (the emitting one) facing down. No environment.
inline Scene lampOverFloor(const LampCase& c) {
    Scene scene;
    scene.source = c.name;
    Material floor, lamp;
    floor.name = "floor";
    floor.diffuse = glm::vec3(kLampFloorAlbedo[0], kLampFloorAlbedo[1], kLampFloorAlbedo[2]);
    lamp.name = "lamp";
    lamp.diffuse = glm::vec3(0.0f);
    lamp.emission = glm::vec3(kLampRadiance[0], kLampRadiance[1], kLampRadiance[2]);
    scene.materials = {floor, lamp};
    float x = float(c.shiftX), f = float(c.floorHalf > 0.0 ? c.floorHalf : 10.0 * c.side),
          l = float(0.5 * c.side), h = float(c.height);
    // Counter-clockwise seen from above (+y) for the floor, from below for the lamp.
    const glm::vec3 floorCorners[4] = {{x - f, 0, -f}, {x - f, 0, f}, {x + f, 0, f}, {x + f, 0, -f}};
    appendQuad(scene, floorCorners, 0);
    const float t = 2.0f * l / float(c.tiles);
    for (int i = 0; i < c.tiles; ++i)
        for (int j = 0; j < c.tiles; ++j) {
            float x0 = x - l + float(i) * t, z0 = -l + float(j) * t, x1 = x0 + t, z1 = z0 + t;
            if (i == c.tiles - 1) x1 = x + l;  // the lamp's edges exactly where one square puts them
            if (j == c.tiles - 1) z1 = l;
            const glm::vec3 lampCorners[4] = {{x0, h, z0}, {x1, h, z0}, {x1, h, z1}, {x0, h, z1}};
            appendQuad(scene, lampCorners, 1);
        }
    return scene;
}

// A pinhole halfway between lamp and floor looking straight down (a camera blocks no light): with a 2
// degree field its image covers a spot of radius 0.012 h under the lamp's centre, where the form
// factor is constant to 1e-5 (lampFormFactorSpread checks it).
constexpr float kLampCameraFovY = 2.0f;

inline Camera lampCamera(const LampCase& c) {
    Camera camera;
    camera.eye = glm::vec3(float(c.shiftX), float(0.5 * c.height), 0.0f);
    camera.target = glm::vec3(float(c.shiftX), 0.0f, 0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.fovY = kLampCameraFovY;
    return camera;
}

// Form factor from a differential area to a parallel X h by Y h rectangle, h above it, with one corner
// straight above it (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors": differential
// area to a parallel rectangle).
inline double cornerFormFactor(double X, double Y) {
    double sx = std::sqrt(1.0 + X * X), sy = std::sqrt(1.0 + Y * Y);
    return (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2.0 * M_PI);
}

// From the floor point (dx, dz) off the lamp's centre, inside its shadow on the floor: the four
// rectangles the point's perpendicular cuts the lamp into, each with a corner above the point.
inline double lampFormFactor(const LampCase& c, double dx, double dz) {
    double l = 0.5 * c.side, h = c.height;
    return cornerFormFactor((l - dx) / h, (l - dz) / h) + cornerFormFactor((l + dx) / h, (l - dz) / h) +
           cornerFormFactor((l - dx) / h, (l + dz) / h) + cornerFormFactor((l + dx) / h, (l + dz) / h);
}

// The floor's radiance rho Le F at floor point p, inside the lamp's shadow on the floor.
inline glm::dvec3 lampFloorRadiance(const LampCase& c, const glm::dvec3& p) {
    double f = lampFormFactor(c, p.x - c.shiftX, p.z);
    return glm::dvec3(kLampFloorAlbedo[0] * kLampRadiance[0], kLampFloorAlbedo[1] * kLampRadiance[1],
                      kLampFloorAlbedo[2] * kLampRadiance[2]) *
           f;
}

// Issue 35's analytic scene: a lamp of side 2, 1 above the floor; F = 0.554126 under its centre (the
// green channel is the issue's albedo 0.5, its radiance scaled by 2). The floor only just covers the
// lamp's shadow, so that its rays' offset (2.3e-5) lifts the floor's radiance by 0.002 %, well inside
// the noise; the default floor, 40 wide, offsets them by 2.3e-4 and lifts it by 0.02 % (measured with
// nee and area sampling: +0.0176 % +- 0.0009 %, against +0.0010 % +- 0.0009 % from this floor).
inline LampCase issue35Lamp() {
    return {"lamp of side 2, 1 above", 2.0, 1.0, 0.0, 2.0};
}

// lampCamera with a 40 degree field: the floor from 0.18 h on either side of the lamp's centre, where
// the form factor falls by some 10 % (each pixel is checked against its own).
inline Camera lampWideCamera(const LampCase& c) {
    Camera camera = lampCamera(c);
    camera.fovY = 40.0f;
    return camera;
}

// How much the form factor varies over the spot the camera sees, relative to its value at the centre.
inline double lampFormFactorSpread(const LampCase& c) {
    double r = 0.5 * c.height * std::tan(0.5 * kLampCameraFovY * M_PI / 180.0);  // half the spot, square
    double f0 = lampFormFactor(c, 0.0, 0.0), spread = 0.0;
    for (double dx : {-r, 0.0, r})
        for (double dz : {-r, 0.0, r}) spread = std::max(spread, std::abs(lampFormFactor(c, dx, dz) - f0));
    return spread / f0;
}

// Expects the floor's radiance rho Le F over the whole image and over each `block` x `block` block,
// within 4 (image) or 4.5 (block) standard errors from the sample variance. Returns the image mean's
// relative error in the first channel, for messages. Every pixel sees the same radiance (the spread is
// checked), so a block's standard error is the image's times the square root of the block count: a
// block's own sample variance is 0 when a rare event (a BSDF ray missing a lamp that fills 99.9 % of
// the sky) happens not to occur in its samples, and would then tolerate no difference at all.
inline double expectLampRadiance(const Accumulation& acc, const LampCase& c, int block) {
    double formFactor = lampFormFactor(c, 0.0, 0.0);
    EXPECT_LT(lampFormFactorSpread(c), 1e-4) << c.name << ": the spot is too large for one value";
    ImageEstimate whole = estimate(acc);
    double blocks = double(acc.width / block) * double(acc.height / block);
    for (int ch = 0; ch < 3; ++ch) {
        double expected = kLampFloorAlbedo[ch] * kLampRadiance[ch] * formFactor;
        EXPECT_GT(whole.standardError[ch], 0.0f) << c.name << ": no noise, no tolerance";
        EXPECT_LT(std::abs(whole.mean[ch] - expected), 4.0 * whole.standardError[ch])
            << c.name << ", channel " << ch << ": mean " << whole.mean[ch] << ", expected " << expected
            << " (F = " << formFactor << "), standard error " << whole.standardError[ch];
        double blockError = whole.standardError[ch] * std::sqrt(blocks);
        for (int y = 0; y + block <= acc.height; y += block)
            for (int x = 0; x + block <= acc.width; x += block) {
                ImageEstimate e = estimate(acc, x, y, block, block);
                EXPECT_LT(std::abs(e.mean[ch] - expected), 4.5 * blockError)
                    << c.name << ", channel " << ch << ", block at " << x << "," << y << ": " << e.mean[ch]
                    << ", expected " << expected << ", standard error " << blockError;
            }
    }
    return whole.mean[0] / (kLampFloorAlbedo[0] * kLampRadiance[0] * formFactor) - 1.0;
}

}  // namespace fp::test
