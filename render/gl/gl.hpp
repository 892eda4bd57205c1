#pragma once
// OpenGL declarations for the renderer: legacy (compatibility profile) GL plus
// the framebuffer-object entry points, all provided by libOSMesa.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
