#include "model/surface_builder.hpp"

#include "geometry/surface_kinds.hpp"

namespace rollspin::model {

namespace {

// A parse error at the scene's file:line:col, pointing into the TOML string
// itself when the key came from a file.
[[noreturn]] void throwParseError(const scene::SceneSpec& spec, const std::string& key, const std::string& text,
                                  const geometry::ExpressionError& e) {
  SourceLoc loc = spec.where(key);
  if (loc.line > 0) loc.column += 1 + e.position();
  throw badInput(loc, "{}: cannot parse \"{}\" at character {}: {}", key, text, e.position() + 1, e.what());
}

}  // namespace

std::shared_ptr<const geometry::Expression> compileExpression(const scene::SceneSpec& spec, const std::string& key,
                                                              const std::string& text,
                                                              std::vector<std::string> variables) {
  try {
    return std::make_shared<const geometry::Expression>(text, std::move(variables));
  } catch (const geometry::ExpressionError& e) {
    throwParseError(spec, key, text, e);
  }
}

std::string surfaceFormulaKey(const scene::SceneSpec& spec) {
  for (const ParamDecl& decl : scene::surfaceKeyDecls(spec.surface.kind))
    if (decl.type == ParamType::Expression) return decl.key;
  return "";
}

std::shared_ptr<const geometry::Surface> buildSurface(const scene::SceneSpec& spec) {
  try {
    return scene::sceneSurfaceKind(spec.surface.kind).geometry->create(spec.surface.params);
  } catch (const geometry::ExpressionError& e) {
    // The kind's formula key (its Expression parameter) is the one to blame.
    const std::string key = surfaceFormulaKey(spec);
    if (!key.empty()) throwParseError(spec, "surface." + key, spec.surface.params.text(key), e);
    throw;
  }
}

}  // namespace rollspin::model
