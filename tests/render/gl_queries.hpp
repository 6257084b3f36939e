// GL calls only the tests make (queries the renderer never needs: is this
// name an object, what does this texture hold), looked up through the
// backend that made the current context (render::glProcAddress), so that
// the table in gl.hpp carries only what rollspin draws with.
#pragma once

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/gl.hpp"

namespace rollspin::render::test_gl {

template <class Function>
Function entry(const char* name) {
  const GlProc address = glProcAddress(name);
  if (address == nullptr) throw std::runtime_error(std::string("the GL backend does not provide ") + name);
  return reinterpret_cast<Function>(address);
}

}  // namespace rollspin::render::test_gl

// TEST_GL(glIsTexture)(name): the entry point with its prototype's type.
#define TEST_GL(name) ::rollspin::render::test_gl::entry<decltype(&::name)>(#name)
