#pragma once
// The light tree (`--light-selection tree`): a binary tree over the emitter triangles that lets light
// sampling choose an emitter by how much it can light the shading point (its power, distance and
// orientation) rather than by power alone (Conty Estevez & Kulla 2018, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting", HPG; the tree Cycles has used since 3.5). The shader descends
// it (glsl/common/light_tree.glsl), at each node choosing a child in proportion to an importance
// bound computed from the child's box, power and cone of emission directions.
//
// The tree is implicit and complete: a heap over the light-selection table's emitter entries in their
// order (pack/layout.h: BVH leaf order, so that neighbouring entries are neighbouring triangles), padded
// with empty leaves to a power of two. Node k has children 2k + 1 and 2k + 2; entry e is leaf
// 2^depth - 1 + e, and the path to it is the binary digits of e, most significant first, which is how
// the shader finds the probability of an emitter a BSDF-sampled ray hit (for MIS) without storing it.
#include <vector>

#include <glm/glm.hpp>

namespace fp {

// One emitter entry: its triangle's vertices (their winding gives the emitting side) and its selection
// power (the power pmf of scene/light_selection.h, whose zeros are never picked).
struct LightTreeEmitter {
    glm::vec3 p0, p1, p2;
    float power = 0.0f;
};

// A bound of a set of one-sided emitters (Conty Estevez & Kulla 2018, section 4.1): their box, total
// power, and a cone (axis, half-angle thetaO) holding every emitting normal. Each emits into the
// hemisphere about its normal, so the cone of emission directions is thetaO + pi / 2 (their theta_e).
struct LightBounds {
    glm::vec3 lo{0.0f}, hi{0.0f};
    float power = 0.0f;  // 0: empty
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    float thetaO = 0.0f;
};

// The smallest cone holding both cones (the paper's Algorithm 1), and the union of two bounds.
LightBounds unionOf(const LightBounds& a, const LightBounds& b);

struct LightTree {
    int depth = 0;                   // levels below the root; 2^depth leaves
    std::vector<LightBounds> nodes;  // 2^(depth + 1) - 1, heap order
};

LightTree buildLightTree(const std::vector<LightTreeEmitter>& emitters);

// The tree's texels (pack/layout.h, lights buffer): 3 per node.
std::vector<glm::vec4> lightTreeTexels(const LightTree& tree);

}  // namespace fp
