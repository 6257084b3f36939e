/* A libEGL for tests that forwards to the real one (glvnd's libEGL.so.1) but
 * lists the client extensions as glvnd does on a machine whose only EGL
 * vendor is NVIDIA's: EGL_EXT_device_base, without the
 * EGL_EXT_device_enumeration and EGL_EXT_device_query it stands for (seen on
 * an H200 with driver 580.159.04). Loaded through ROLLSPIN_EGL_LIBRARY. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*Function)(void);

/* The real libEGL's `name` (a function pointer may not be cast from dlsym's
 * void* in ISO C: copied instead). */
static Function real(const char* name) {
  static void* handle = NULL;
  if (handle == NULL) handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
  void* symbol = handle != NULL ? dlsym(handle, name) : NULL;
  if (symbol == NULL) {
    fprintf(stderr, "egl_device_base_shim: no %s in libEGL.so.1\n", name);
    abort();
  }
  Function f;
  memcpy(&f, &symbol, sizeof f);
  return f;
}

/* `list` without the word `word` (space-separated names). */
static void removeWord(char* list, const char* word) {
  const size_t n = strlen(word);
  for (char* at = list; (at = strstr(at, word)) != NULL;) {
    const int starts = at == list || at[-1] == ' ';
    const int ends = at[n] == '\0' || at[n] == ' ';
    if (!starts || !ends) {
      at += n;
      continue;
    }
    memmove(at, at + n + (at[n] == ' '), strlen(at + n + (at[n] == ' ')) + 1);
  }
}

const char* eglQueryString(EGLDisplay display, EGLint name) {
  const char* answer = ((PFNEGLQUERYSTRINGPROC)real("eglQueryString"))(display, name);
  if (display != EGL_NO_DISPLAY || name != EGL_EXTENSIONS || answer == NULL) return answer;
  static char client[8192];
  snprintf(client, sizeof client, "%s", answer);
  removeWord(client, "EGL_EXT_device_enumeration");
  removeWord(client, "EGL_EXT_device_query");
  if (strstr(client, "EGL_EXT_device_base") == NULL)
    strncat(client, " EGL_EXT_device_base", sizeof client - 1 - strlen(client));
  return client;
}

__eglMustCastToProperFunctionPointerType eglGetProcAddress(const char* name) {
  return ((PFNEGLGETPROCADDRESSPROC)real("eglGetProcAddress"))(name);
}
EGLint eglGetError(void) { return ((PFNEGLGETERRORPROC)real("eglGetError"))(); }
EGLDisplay eglGetPlatformDisplay(EGLenum platform, void* native, const EGLAttrib* attributes) {
  return ((PFNEGLGETPLATFORMDISPLAYPROC)real("eglGetPlatformDisplay"))(platform, native, attributes);
}
EGLBoolean eglInitialize(EGLDisplay d, EGLint* major, EGLint* minor) {
  return ((PFNEGLINITIALIZEPROC)real("eglInitialize"))(d, major, minor);
}
EGLBoolean eglTerminate(EGLDisplay d) { return ((PFNEGLTERMINATEPROC)real("eglTerminate"))(d); }
EGLBoolean eglBindAPI(EGLenum api) { return ((PFNEGLBINDAPIPROC)real("eglBindAPI"))(api); }
EGLBoolean eglChooseConfig(EGLDisplay d, const EGLint* wanted, EGLConfig* configs, EGLint size, EGLint* found) {
  return ((PFNEGLCHOOSECONFIGPROC)real("eglChooseConfig"))(d, wanted, configs, size, found);
}
EGLContext eglCreateContext(EGLDisplay d, EGLConfig config, EGLContext share, const EGLint* attributes) {
  return ((PFNEGLCREATECONTEXTPROC)real("eglCreateContext"))(d, config, share, attributes);
}
EGLBoolean eglMakeCurrent(EGLDisplay d, EGLSurface draw, EGLSurface read, EGLContext c) {
  return ((PFNEGLMAKECURRENTPROC)real("eglMakeCurrent"))(d, draw, read, c);
}
EGLBoolean eglDestroyContext(EGLDisplay d, EGLContext c) {
  return ((PFNEGLDESTROYCONTEXTPROC)real("eglDestroyContext"))(d, c);
}
EGLBoolean eglReleaseThread(void) { return ((PFNEGLRELEASETHREADPROC)real("eglReleaseThread"))(); }
