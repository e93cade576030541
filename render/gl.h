// The one way render/ includes OpenGL: glad's core-profile 4.5 declarations, each a pointer
// loaded from the current context's backend (gl_context.cpp). Do not mix with <GL/gl.h>.
#pragma once
#include <glad/gl.h>
