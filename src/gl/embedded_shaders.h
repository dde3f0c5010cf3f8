#pragma once
// The glsl/ tree compiled into the binary (see cmake/embed_files.cmake), keyed by path below glsl/.
#include <map>
#include <string>

namespace fp {

const std::map<std::string, std::string>& embeddedShaders();

}  // namespace fp
