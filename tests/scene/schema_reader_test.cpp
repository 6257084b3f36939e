// scene/schema_reader: one TOML document read into a SceneSpec, in process
// (no loader, no file): its helpers' wording (a node described, keys
// joined, a range written out, an unknown key answered), every key's
// source remembered (its line, an override's argument, an inherited file's
// name), and the messages of the rules the reader applies itself: a wrong
// type, a value out of range, a direction of zero length, a path off its
// surface, a key of another kind, a plate without its radius, a tolerance
// with a fixed-step method, too few points, an empty range of t.
#include "scene/schema_reader.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <map>
#include <set>
#include <string>

#include "core/error.hpp"
#include "support/cli_runner.hpp"

namespace rollspin::scene::schema_reader_tests {
namespace {

using rollspin::test::has;

SceneSpec readSceneText(const std::string& text, const std::map<std::string, SourceLoc>& overrides = {},
                        const std::string& parsedAs = "scene.toml") {
  const toml::table root = toml::parse(text, parsedAs);
  return schema::Reader(root, "scene.toml", overrides).read();
}

// The refusal of a document: its message (the test fails when it is read).
Error refusalOf(const std::string& text) {
  try {
    readSceneText(text);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "read without complaint:\n" << text;
  return Error(ErrorKind::Runtime, {}, "");
}

TEST(SchemaReader, DescribesANodeByItsTypeAndValue) {
  const toml::table t = toml::parse(R"(s = "x"
i = 3
f = 2.5
b = false
a = [1, 2]
d = 1979-05-27
[t]
)");
  EXPECT_EQ(schema::describeNode(*t.get("s")), "string \"x\"");
  EXPECT_EQ(schema::describeNode(*t.get("i")), "integer 3");
  EXPECT_EQ(schema::describeNode(*t.get("f")), "number 2.5");
  EXPECT_EQ(schema::describeNode(*t.get("b")), "boolean false");
  EXPECT_EQ(schema::describeNode(*t.get("a")), "an array");
  EXPECT_EQ(schema::describeNode(*t.get("t")), "a table");
  EXPECT_EQ(schema::describeNode(*t.get("d")), "a date/time");
}

TEST(SchemaReader, JoinsKeysInOrderWithCommas) {
  EXPECT_EQ(schema::joinKeys({"turns", "radius", "direction"}), "direction, radius, turns");
  EXPECT_EQ(schema::joinKeys({"radius"}), "radius");
  EXPECT_EQ(schema::joinKeys({}), "");
}

TEST(SchemaReader, ABoundIncludesItsEndUnlessItIsOpen) {
  const Bounds closed{0.0, 1.0, false, false}, open{0.0, 1.0, true, true}, above{0.0, std::nullopt, true, false};
  EXPECT_TRUE(schema::withinBounds(closed, 0.0));
  EXPECT_TRUE(schema::withinBounds(closed, 1.0));
  EXPECT_FALSE(schema::withinBounds(closed, 1.0000001));
  EXPECT_FALSE(schema::withinBounds(closed, -1e-300));
  EXPECT_FALSE(schema::withinBounds(open, 0.0));
  EXPECT_FALSE(schema::withinBounds(open, 1.0));
  EXPECT_TRUE(schema::withinBounds(open, 0.5));
  EXPECT_FALSE(schema::withinBounds(above, 0.0));
  EXPECT_TRUE(schema::withinBounds(above, 1e300) && schema::withinBounds(above, 1e-300));
  EXPECT_TRUE(schema::withinBounds(Bounds{}, -1e300)) << "no end: unbounded";
}

TEST(SchemaReader, AnExpectationSaysTheNounTheRangeAndTheUnit) {
  // The header's own example.
  EXPECT_EQ(schema::expectation("an image size", "pixels", "", Bounds{1.0, 8192.0}),
            "an image size in [1, 8192] pixels");
  EXPECT_EQ(schema::expectation("a fraction", "", "", Bounds{0.0, 1.0, true, false}), "a fraction in (0, 1]");
  EXPECT_EQ(schema::expectation("a radius", "", "", Bounds{0.0, std::nullopt, true}), "a radius > 0");
  EXPECT_EQ(schema::expectation("a count", "", "", Bounds{0.0, std::nullopt}), "a count >= 0");
  EXPECT_EQ(schema::expectation("an angle", "degrees", "", Bounds{std::nullopt, 90.0, false, true}),
            "an angle < 90 degrees");
  // The step limit as a power of ten, not 100000000000.
  EXPECT_EQ(schema::expectation("a step count", "", "", Bounds{1.0, 1e11}), "a step count in [1, 1e11]");
  EXPECT_EQ(schema::expectation("a radius", "", "", std::nullopt), "a radius");
  EXPECT_EQ(schema::expectation("ignored", "ignored", "one of 1, 2 or 4", Bounds{1.0, 4.0}), "one of 1, 2 or 4");
}

TEST(SchemaReader, AnUnknownKeySuggestsTheNearestAndListsTheTable) {
  const SourceLoc at{"scene.toml", 3, 1};
  const Error typo = schema::unknownKey(at, "path.radus", "radus", "[path]", {"radius", "turns"});
  EXPECT_EQ(typo.message(), "path.radus: unknown key; did you mean `radius`? [path] accepts: radius, turns");
  EXPECT_EQ(typo.where().str(), "scene.toml:3:1");
  EXPECT_EQ(typo.kind(), ErrorKind::BadInput);
  // Nothing near: the list alone; a table that ends with ':' is used as written.
  EXPECT_EQ(schema::unknownKey(at, "camera", "camera", "a scene has the tables:", {"ball", "path"}).message(),
            "camera: unknown key; a scene has the tables: ball, path");
  // The key without its unit, or in another unit: the key in the schema's unit alone.
  EXPECT_EQ(schema::unknownKey(at, "path.colatitude", "colatitude", "[path]", {"colatitude_deg", "turns"}).message(),
            "path.colatitude: unknown key; did you mean `colatitude_deg` (in degrees)?");
  EXPECT_EQ(schema::unknownKey(at, "figure.width_cm", "width_cm", "[figure]", {"width_mm", "font"}).message(),
            "figure.width_cm: unknown key; did you mean `width_mm` (in millimetres)?");
}

TEST(SchemaReader, AnEmptyDocumentIsTheDefaults) {
  const SceneSpec spec = readSceneText("");
  const SceneSpec defaults;
  EXPECT_EQ(spec.sourceFile, "scene.toml");
  EXPECT_EQ(spec.ball.radius, defaults.ball.radius);
  EXPECT_EQ(spec.surface.kind, SurfaceKind::Plane);
  EXPECT_EQ(spec.path.kind, PathKind::Circle);
  EXPECT_EQ(spec.path.radius, defaults.path.radius);
  EXPECT_EQ(spec.render.width, defaults.render.width);
  EXPECT_FALSE(spec.plate);
  EXPECT_TRUE(spec.segments.empty());
  EXPECT_TRUE(spec.locations.empty()) << "no key given, none located";
}

TEST(SchemaReader, EachKeyRemembersWhereItWasSet) {
  const std::string text = "[ball]\nradius = 0.5\n\n[path]\n  turns = 2\n";
  const SceneSpec spec = readSceneText(text);
  EXPECT_EQ(spec.ball.radius, 0.5);
  EXPECT_EQ(spec.path.turns, 2.0);
  EXPECT_EQ(spec.where("ball.radius").str(), "scene.toml:2:10");
  EXPECT_EQ(spec.where("path.turns").str(), "scene.toml:5:11");
  EXPECT_EQ(spec.where("ball").line, 1);
  EXPECT_EQ(spec.where("path.radius").line, 0) << "a default has the file, no line";
  // A --set value names its argument.
  const SceneSpec set = readSceneText(text, {{"ball.radius", SourceLoc{"--set ball.radius=0.5"}}});
  EXPECT_EQ(set.where("ball.radius").str(), "--set ball.radius=0.5");
  // A value inherited through `extends` names its own file.
  const SceneSpec inherited = readSceneText(text, {}, "base.toml");
  EXPECT_EQ(inherited.where("path.turns").str(), "base.toml:5:11");
}

TEST(SchemaReader, AWrongTypeNamesTheKeyWhatItTakesAndWhatItGot) {
  const Error e = refusalOf("[ball]\nradius = \"big\"\n");
  EXPECT_EQ(e.message(), "ball.radius: expected a number, got string \"big\"");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(refusalOf("[render]\nshadow = 1\n").message(), "render.shadow: expected true or false, got integer 1");
  EXPECT_EQ(refusalOf("[render]\nwidth = 640.5\n").message(), "render.width: expected an integer, got number 640.5");
  EXPECT_EQ(refusalOf("render = 3\n").message(), "render: expected a table [render], got integer 3");
  EXPECT_EQ(refusalOf("[ball]\nradius = inf\n").message(), "ball.radius: expected a finite number, got number inf");
}

TEST(SchemaReader, AnIntegerKeyTakesAWholeNumberWrittenAsAFloat) {
  // 1e3 is how the docs write limits.
  EXPECT_EQ(readSceneText("[render]\nwidth = 1e3\n").render.width, 1000);
}

TEST(SchemaReader, AValueOutOfRangeSaysTheRange) {
  EXPECT_EQ(refusalOf("[render]\nwidth = 0\n").message(),
            "render.width: expected an image size in [1, 8192] pixels, got 0");
  EXPECT_EQ(refusalOf("[ball]\nradius = -1\n").message(), "ball.radius: expected a radius > 0, got -1");
  EXPECT_NO_THROW(readSceneText("[render]\nwidth = 8192\n")) << "the end of a closed range is in it";
}

TEST(SchemaReader, AChoiceListsItsChoices) {
  const Error e = refusalOf("[render]\nlayout = \"diagonal\"\n");
  EXPECT_TRUE(has(e.message(), "render.layout: expected "));
  for (const char* choice : {"\"side-by-side\"", "\"inset\"", "\"ball\"", "\"twin\""})
    EXPECT_TRUE(has(e.message(), choice)) << e.message();
  EXPECT_TRUE(has(e.message(), "got string \"diagonal\""));
  EXPECT_EQ(readSceneText("[render]\nlayout = \"twin\"\n").render.layout, RenderLayout::Twin);
}

TEST(SchemaReader, ASurfaceDirectionIsNormalisedAndNeverZero) {
  const SceneSpec spec = readSceneText("[surface]\nnormal = [0, 0, 2]\n");
  EXPECT_EQ(spec.surface.params.vector("normal"), (Vec3{0.0, 0.0, 1.0}));
  const SceneSpec tilted = readSceneText("[surface]\nnormal = [3, 0, 4]\n");
  const Vec3 n = tilted.surface.params.vector("normal");
  EXPECT_NEAR(n[0], 0.6, 1e-15);
  EXPECT_NEAR(n[2], 0.8, 1e-15);
  EXPECT_EQ(refusalOf("[surface]\nnormal = [0, 0, 0]\n").message(),
            "surface.normal: expected a non-zero vector, got [0, 0, 0]");
  EXPECT_EQ(refusalOf("[surface]\nnormal = [0, 1]\n").message(),
            "surface.normal: expected an array of 3 finite numbers [x, y, z], got an array");
  EXPECT_EQ(refusalOf("[surface]\nnormal = [0, \"up\", 1]\n").message(),
            "surface.normal: expected an array of 3 finite numbers [x, y, z], got element 1 = string \"up\"");
}

TEST(SchemaReader, AnUnknownTableIsAnsweredWithTheScenesTables) {
  const Error e = refusalOf("[camera]\nazimuth_deg = 3\n");
  EXPECT_TRUE(has(e.message(), "camera: unknown key;")) << e.message();
  EXPECT_TRUE(has(e.message(), "a scene has the tables:")) << e.message();
  EXPECT_TRUE(has(e.message(), "ball") && has(e.message(), "render")) << e.message();
  const Error key = refusalOf("[ball]\nradus = 1\n");
  EXPECT_TRUE(has(key.message(), "ball.radus: unknown key; did you mean `radius`? [ball] accepts:")) << key.message();
}

TEST(SchemaReader, ACurvedSurfaceTakesItsOwnPathWhenNoneIsNamed) {
  EXPECT_EQ(readSceneText("[surface]\nkind = \"sphere\"\n").path.kind,
            sceneSurfaceKind(SurfaceKind::Sphere).defaultPath);
  EXPECT_EQ(readSceneText("[surface]\nkind = \"saddle\"\n").path.kind,
            sceneSurfaceKind(SurfaceKind::Saddle).defaultPath);
  EXPECT_EQ(readSceneText("").path.kind, PathKind::Circle);
}

TEST(SchemaReader, APathThatLeavesItsSurfaceIsRefused) {
  const Error e = refusalOf("[path]\nkind = \"helix\"\n");
  EXPECT_EQ(e.message(),
            "path.kind: a helix path lies on a cylinder, but surface.kind is \"plane\" (the path would leave the "
            "surface)");
  EXPECT_EQ(e.where().line, 2);
  // A line in the plane must lie in it.
  const Error off = refusalOf("[path]\nkind = \"line\"\ndirection_vector = [1, 0, 1]\n");
  EXPECT_TRUE(has(off.message(), "path.direction_vector: the line leaves the surface")) << off.message();
  EXPECT_NO_THROW(readSceneText("[path]\nkind = \"line\"\ndirection_vector = [1, 1, 0]\n"));
}

TEST(SchemaReader, AKeyOfAnotherKindIsRefusedNamingWhereItApplies) {
  const Error path = refusalOf("[path]\nkind = \"line\"\ncolatitude_deg = 30\n");
  EXPECT_EQ(path.message(),
            "path.colatitude_deg: applies to path kind parallel on a sphere only; this path is a line on a plane");
  EXPECT_EQ(path.where().line, 3);
  const Error surface = refusalOf("[surface]\nkind = \"plane\"\nradius = 3\n");
  EXPECT_TRUE(has(surface.message(), "surface.radius: applies to kind = ")) << surface.message();
  EXPECT_TRUE(has(surface.message(), "\"sphere\"")) << surface.message();
  EXPECT_TRUE(has(surface.message(), "only; this surface is a plane")) << surface.message();
}

TEST(SchemaReader, APlateNeedsItsRadiusAndDrivesTheCircle) {
  EXPECT_TRUE(has(refusalOf("[plate]\n").message(), "plate.radius: missing;"));
  const Error both = refusalOf("[plate]\nradius = 2\n[path]\nradius = 1\n");
  EXPECT_TRUE(has(both.message(), "path.radius: conflicts with [plate]")) << both.message();
  const Error line = refusalOf("[plate]\nradius = 2\n[path]\nkind = \"line\"\n");
  EXPECT_TRUE(has(line.message(), "path.kind: with [plate]")) << line.message();
  const SceneSpec spec = readSceneText("[plate]\nradius = 2\n");
  ASSERT_TRUE(spec.plate);
  EXPECT_EQ(spec.plate->radius, 2.0);
}

TEST(SchemaReader, ATolerancePicksAnAdaptiveMethodAndStepsAFixedOne) {
  EXPECT_EQ(readSceneText("[solver]\ntolerance = 1e-8\n").solver.method, "frame6a");
  EXPECT_EQ(readSceneText("[solver]\nmethod = \"rk45\"\ntolerance = 1e-8\n").solver.method, "rk45");
  EXPECT_EQ(readSceneText("[solver]\nsteps = 100\n").solver.method, SolverSpec{}.method);
  EXPECT_TRUE(has(refusalOf("[solver]\nmethod = \"magnus4\"\ntolerance = 1e-8\n").message(),
                  "solver.tolerance: applies to the adaptive methods ("));
  EXPECT_TRUE(has(refusalOf("[solver]\nmethod = \"rk45\"\nsteps = 100\n").message(),
                  "solver.steps: method \"rk45\" chooses its own steps"));
}

TEST(SchemaReader, APathAndASegmentTogetherAreRefused) {
  const Error e = refusalOf("[path]\nturns = 1\n[[segment]]\nhold = 1\n");
  EXPECT_TRUE(has(e.message(), "path: a scene has either one [path] or a storyboard")) << e.message();
}

TEST(SchemaReader, PointsNeedEnoughOfThemAllOfOneDimension) {
  EXPECT_EQ(refusalOf("[path]\nkind = \"points\"\npoints = [[0, 0]]\n").message(),
            "path.points: expected at least 2 points for an open path, got 1");
  EXPECT_EQ(refusalOf("[path]\nkind = \"points\"\nclosed = true\npoints = [[0, 0], [1, 0]]\n").message(),
            "path.points: expected at least 3 points for a closed path, got 2");
  EXPECT_EQ(refusalOf("[path]\nkind = \"points\"\npoints = [[0, 0], [1, 0, 0]]\n").message(),
            "path.points: expected all points with the same number of coordinates, got point 2 with 3");
  const SceneSpec spec = readSceneText("[path]\nkind = \"points\"\npoints = [[0, 0], [1, 0.5]]\n");
  EXPECT_EQ(spec.path.points, (std::vector<std::vector<double>>{{0.0, 0.0}, {1.0, 0.5}}));
}

TEST(SchemaReader, AUvPathNeedsTEndAfterTStart) {
  const Error e = refusalOf("[path]\nkind = \"uv\"\nt_start = 1\nt_end = 0.5\n");
  EXPECT_EQ(e.message(), "path.t_end: expected t_end > t_start, got [1, 0.5]");
  EXPECT_EQ(e.where().line, 4);
  EXPECT_TRUE(
      has(refusalOf("[path]\nkind = \"uv\"\nu = \"  \"\n").message(), "path.u: expected a non-empty expression"));
}

}  // namespace
}  // namespace rollspin::scene::schema_reader_tests
