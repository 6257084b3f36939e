// OSMesa's own entry points, resolved with dlsym by loadOsMesa() (gl.hpp):
// render/ never links libOSMesa at build time.
#pragma once

#include <GL/osmesa.h>

namespace rollspin::render::osmesa_api {
extern decltype(&OSMesaCreateContextAttribs) createContextAttribs;
extern decltype(&OSMesaMakeCurrent) makeCurrent;
extern decltype(&OSMesaDestroyContext) destroyContext;
extern decltype(&OSMesaGetProcAddress) getProcAddress;
}  // namespace rollspin::render::osmesa_api
