// `rollspin --version`: the release, `git describe` of the source when built
// from a clone, and (with --verbose) the GL backend a render would use.
#pragma once

#include <string>

namespace rollspin::cli {

// "rollspin 0.1.0 (git v0.1-12-gabc1234)" or "rollspin 0.1.0 (not built from a git clone)".
[[nodiscard]] std::string versionLine();

// What a render would draw with: the context's own description, or why none
// can be made. Creates (and drops) a context: only for --version --verbose.
[[nodiscard]] std::string glBackendDescription();

}  // namespace rollspin::cli
