#pragma once
// The GPU layout (pack/layout.h) as the shaders see it: its constants as #defines for
// glsl/common/scene_data.glsl, so that the packer and the shaders cannot drift apart.
#include <cstdint>

#include "gl/shader_source.h"

namespace fp::layout {

// The layout's defines; with `images`, also SCENE_READS_IMAGES and the extension it needs.
ShaderDefines layoutDefines(bool images = false);

// The most entries glsl/common/intersect.glsl's traversal stack can have (shiftStack's runs).
constexpr uint32_t kMaxTraversalStack = 259;

// The traversal stack's entries (BVH_STACK_SIZE) for a tree whose traversal can hold `treeEntries`
// (PackedScene::stackEntries): as many as it needs, no more, since the shader shifts every entry at every
// node visit; at least the 4 that shiftStack needs. Throws fp::Error for a tree that needs more than
// kMaxTraversalStack.
uint32_t traversalStackEntries(uint32_t treeEntries);

}  // namespace fp::layout
