// The one way render/ includes OpenGL: core-profile declarations with prototypes, resolved
// directly against libOSMesa. Do not mix with <GL/gl.h>.
// libOSMesa exports the entry points of GL <= 4.4 only: the 4.5 direct-state-access functions
// (glCreate*, glNamed*, glTexture*, glBindTextureUnit, ...) link-fail. Use bind-to-edit calls.
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
