#pragma once
// The one include for OpenGL in the engine: the glad loader generated at
// configure time (see the top-level CMakeLists.txt for why glad, not epoxy).
#include <glad/gl.h>
