// tinygltf's implementation, compiled once with the configuration of gltf_internal.h. Its header is a
// system header (/usr/include), so our warning flags do not apply to its code.
#define TINYGLTF_IMPLEMENTATION
#include "scene/gltf_internal.h"
