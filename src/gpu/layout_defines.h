#pragma once
// The GPU layout (pack/layout.h) as the shaders see it: its constants as #defines for
// glsl/common/scene_data.glsl, so that the packer and the shaders cannot drift apart.
#include "gl/shader_source.h"

namespace fp::layout {

// The layout's defines; with `images`, also SCENE_READS_IMAGES and the extension it needs.
ShaderDefines layoutDefines(bool images = false);

}  // namespace fp::layout
