// The one place render/ includes OpenGL: the 4.5 core profile (glcorearb.h)
// and a table of function pointers filled at run time by the context backend
// that made the current context (gl_backends.cpp chooses it; each backend
// loads its library with dlopen and hands its GetProcAddress to
// loadGlFunctions). The binary therefore needs no GL library to start:
// `solve` and `timeline` run on a machine without one, and only a job that
// draws loads one. Calls are written as usual (glDrawArrays(...)); the macros
// below route them through the table. A new GL call needs one line in
// ROLLSPIN_GL_FUNCTIONS.
#pragma once

// Prototypes are declared (never linked: only their types are used) so each
// table entry can take its exact type from decltype; GL/gl.h must come before
// the renaming macros (a backend's own header may include it again).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glcorearb.h>

#include <string_view>

#define ROLLSPIN_GL_FUNCTIONS(X) \
  X(glActiveTexture) \
  X(glAttachShader) \
  X(glBindBuffer) \
  X(glBindFramebuffer) \
  X(glBindRenderbuffer) \
  X(glBindTexture) \
  X(glBindTextureUnit) \
  X(glBindVertexArray) \
  X(glBlendFuncSeparate) \
  X(glBlitFramebuffer) \
  X(glBufferData) \
  X(glCheckFramebufferStatus) \
  X(glClear) \
  X(glClearBufferfv) \
  X(glClearColor) \
  X(glColorMask) \
  X(glCompileShader) \
  X(glCreateProgram) \
  X(glCreateShader) \
  X(glCreateTextures) \
  X(glCullFace) \
  X(glDeleteBuffers) \
  X(glDeleteFramebuffers) \
  X(glDeleteProgram) \
  X(glDeleteRenderbuffers) \
  X(glDeleteShader) \
  X(glDeleteTextures) \
  X(glDeleteVertexArrays) \
  X(glDepthFunc) \
  X(glDepthMask) \
  X(glDisable) \
  X(glDrawArrays) \
  X(glDrawBuffer) \
  X(glDrawBuffers) \
  X(glDrawElements) \
  X(glEnable) \
  X(glEnableVertexAttribArray) \
  X(glFinish) \
  X(glFramebufferRenderbuffer) \
  X(glFramebufferTexture2D) \
  X(glGenBuffers) \
  X(glGenFramebuffers) \
  X(glGenRenderbuffers) \
  X(glGenTextures) \
  X(glGenVertexArrays) \
  X(glGenerateMipmap) \
  X(glGetError) \
  X(glGetIntegerv) \
  X(glGetProgramInfoLog) \
  X(glGetProgramiv) \
  X(glGetShaderInfoLog) \
  X(glGetShaderiv) \
  X(glGetString) \
  X(glGetUniformLocation) \
  X(glIsEnabled) \
  X(glLinkProgram) \
  X(glMultiDrawArrays) \
  X(glMultiDrawElements) \
  X(glPixelStorei) \
  X(glPolygonOffset) \
  X(glReadBuffer) \
  X(glReadPixels) \
  X(glRenderbufferStorage) \
  X(glRenderbufferStorageMultisample) \
  X(glScissor) \
  X(glShaderSource) \
  X(glTexImage2D) \
  X(glTexParameteri) \
  X(glTexStorage2D) \
  X(glTexStorage2DMultisample) \
  X(glTexSubImage2D) \
  X(glTextureParameteri) \
  X(glTextureStorage2D) \
  X(glTextureView) \
  X(glUniform1f) \
  X(glUniform1i) \
  X(glUniform1ui) \
  X(glUniform2fv) \
  X(glUniform2i) \
  X(glUniform3fv) \
  X(glUniform4fv) \
  X(glUniformMatrix3fv) \
  X(glUniformMatrix4fv) \
  X(glUseProgram) \
  X(glVertexAttribPointer) \
  X(glViewport)

namespace rollspin::render::gl_api {
#define ROLLSPIN_GL_DECLARE(name) \
  using name##_type = decltype(&::name); \
  extern name##_type name;
ROLLSPIN_GL_FUNCTIONS(ROLLSPIN_GL_DECLARE)
#undef ROLLSPIN_GL_DECLARE
}  // namespace rollspin::render::gl_api

#define glActiveTexture ::rollspin::render::gl_api::glActiveTexture
#define glAttachShader ::rollspin::render::gl_api::glAttachShader
#define glBindBuffer ::rollspin::render::gl_api::glBindBuffer
#define glBindFramebuffer ::rollspin::render::gl_api::glBindFramebuffer
#define glBindRenderbuffer ::rollspin::render::gl_api::glBindRenderbuffer
#define glBindTexture ::rollspin::render::gl_api::glBindTexture
#define glBindTextureUnit ::rollspin::render::gl_api::glBindTextureUnit
#define glBindVertexArray ::rollspin::render::gl_api::glBindVertexArray
#define glBlendFuncSeparate ::rollspin::render::gl_api::glBlendFuncSeparate
#define glBlitFramebuffer ::rollspin::render::gl_api::glBlitFramebuffer
#define glBufferData ::rollspin::render::gl_api::glBufferData
#define glCheckFramebufferStatus ::rollspin::render::gl_api::glCheckFramebufferStatus
#define glClear ::rollspin::render::gl_api::glClear
#define glClearBufferfv ::rollspin::render::gl_api::glClearBufferfv
#define glClearColor ::rollspin::render::gl_api::glClearColor
#define glColorMask ::rollspin::render::gl_api::glColorMask
#define glCompileShader ::rollspin::render::gl_api::glCompileShader
#define glCreateProgram ::rollspin::render::gl_api::glCreateProgram
#define glCreateShader ::rollspin::render::gl_api::glCreateShader
#define glCreateTextures ::rollspin::render::gl_api::glCreateTextures
#define glCullFace ::rollspin::render::gl_api::glCullFace
#define glDeleteBuffers ::rollspin::render::gl_api::glDeleteBuffers
#define glDeleteFramebuffers ::rollspin::render::gl_api::glDeleteFramebuffers
#define glDeleteProgram ::rollspin::render::gl_api::glDeleteProgram
#define glDeleteRenderbuffers ::rollspin::render::gl_api::glDeleteRenderbuffers
#define glDeleteShader ::rollspin::render::gl_api::glDeleteShader
#define glDeleteTextures ::rollspin::render::gl_api::glDeleteTextures
#define glDeleteVertexArrays ::rollspin::render::gl_api::glDeleteVertexArrays
#define glDepthFunc ::rollspin::render::gl_api::glDepthFunc
#define glDepthMask ::rollspin::render::gl_api::glDepthMask
#define glDisable ::rollspin::render::gl_api::glDisable
#define glDrawArrays ::rollspin::render::gl_api::glDrawArrays
#define glDrawBuffer ::rollspin::render::gl_api::glDrawBuffer
#define glDrawBuffers ::rollspin::render::gl_api::glDrawBuffers
#define glDrawElements ::rollspin::render::gl_api::glDrawElements
#define glEnable ::rollspin::render::gl_api::glEnable
#define glEnableVertexAttribArray ::rollspin::render::gl_api::glEnableVertexAttribArray
#define glFinish ::rollspin::render::gl_api::glFinish
#define glFramebufferRenderbuffer ::rollspin::render::gl_api::glFramebufferRenderbuffer
#define glFramebufferTexture2D ::rollspin::render::gl_api::glFramebufferTexture2D
#define glGenBuffers ::rollspin::render::gl_api::glGenBuffers
#define glGenFramebuffers ::rollspin::render::gl_api::glGenFramebuffers
#define glGenRenderbuffers ::rollspin::render::gl_api::glGenRenderbuffers
#define glGenTextures ::rollspin::render::gl_api::glGenTextures
#define glGenVertexArrays ::rollspin::render::gl_api::glGenVertexArrays
#define glGenerateMipmap ::rollspin::render::gl_api::glGenerateMipmap
#define glGetError ::rollspin::render::gl_api::glGetError
#define glGetIntegerv ::rollspin::render::gl_api::glGetIntegerv
#define glGetProgramInfoLog ::rollspin::render::gl_api::glGetProgramInfoLog
#define glGetProgramiv ::rollspin::render::gl_api::glGetProgramiv
#define glGetShaderInfoLog ::rollspin::render::gl_api::glGetShaderInfoLog
#define glGetShaderiv ::rollspin::render::gl_api::glGetShaderiv
#define glGetString ::rollspin::render::gl_api::glGetString
#define glGetUniformLocation ::rollspin::render::gl_api::glGetUniformLocation
#define glIsEnabled ::rollspin::render::gl_api::glIsEnabled
#define glLinkProgram ::rollspin::render::gl_api::glLinkProgram
#define glMultiDrawArrays ::rollspin::render::gl_api::glMultiDrawArrays
#define glMultiDrawElements ::rollspin::render::gl_api::glMultiDrawElements
#define glPixelStorei ::rollspin::render::gl_api::glPixelStorei
#define glPolygonOffset ::rollspin::render::gl_api::glPolygonOffset
#define glReadBuffer ::rollspin::render::gl_api::glReadBuffer
#define glReadPixels ::rollspin::render::gl_api::glReadPixels
#define glRenderbufferStorage ::rollspin::render::gl_api::glRenderbufferStorage
#define glRenderbufferStorageMultisample ::rollspin::render::gl_api::glRenderbufferStorageMultisample
#define glScissor ::rollspin::render::gl_api::glScissor
#define glShaderSource ::rollspin::render::gl_api::glShaderSource
#define glTexImage2D ::rollspin::render::gl_api::glTexImage2D
#define glTexParameteri ::rollspin::render::gl_api::glTexParameteri
#define glTexStorage2D ::rollspin::render::gl_api::glTexStorage2D
#define glTexStorage2DMultisample ::rollspin::render::gl_api::glTexStorage2DMultisample
#define glTexSubImage2D ::rollspin::render::gl_api::glTexSubImage2D
#define glTextureParameteri ::rollspin::render::gl_api::glTextureParameteri
#define glTextureStorage2D ::rollspin::render::gl_api::glTextureStorage2D
#define glTextureView ::rollspin::render::gl_api::glTextureView
#define glUniform1f ::rollspin::render::gl_api::glUniform1f
#define glUniform1i ::rollspin::render::gl_api::glUniform1i
#define glUniform1ui ::rollspin::render::gl_api::glUniform1ui
#define glUniform2fv ::rollspin::render::gl_api::glUniform2fv
#define glUniform2i ::rollspin::render::gl_api::glUniform2i
#define glUniform3fv ::rollspin::render::gl_api::glUniform3fv
#define glUniform4fv ::rollspin::render::gl_api::glUniform4fv
#define glUniformMatrix3fv ::rollspin::render::gl_api::glUniformMatrix3fv
#define glUniformMatrix4fv ::rollspin::render::gl_api::glUniformMatrix4fv
#define glUseProgram ::rollspin::render::gl_api::glUseProgram
#define glVertexAttribPointer ::rollspin::render::gl_api::glVertexAttribPointer
#define glViewport ::rollspin::render::gl_api::glViewport

namespace rollspin::render {
// A backend's GetProcAddress (eglGetProcAddress and its kin): the address of
// a GL entry point for the context it made, or null.
using GlProc = void (*)();
using GlProcResolver = GlProc (*)(const char* name);
// Fills the table from `resolve`, called with the backend's context current
// (the table serves one backend at a time: the last one to fill it). Throws
// rollspin::Error (Runtime) naming `library` and the first missing function.
void loadGlFunctions(GlProcResolver resolve, std::string_view library);
// Any GL entry point of the backend that filled the table last, for a call
// the table does not carry (the tests' queries: glIsTexture,
// glGetTextureImage); null when there is none or no table was filled.
GlProc glProcAddress(const char* name);
}  // namespace rollspin::render
