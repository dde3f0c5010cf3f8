#pragma once
// The one way this project includes OpenGL: glad's 4.1 core loader (third_party/glad).
#include <glad/gl.h>
