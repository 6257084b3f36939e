// The one place render/ includes OpenGL: the 4.5 core profile prototypes
// (glcorearb.h). The functions resolve against the current context's library
// (libOSMesa today); nothing outside render/ includes this header.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
