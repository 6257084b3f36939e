// Storyboards ([[segment]] entries) through the real CLI: malformed segments
// exit 2 naming segment[k].key at file:line:col and write nothing; a good
// storyboard solves, streams a timeline whose s runs on through the segments
// with a segment column, prints its resolved segments and reads them back;
// extends replaces a parent's path or segments as a whole.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <numbers>
#include <sstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

namespace {

const rollspin::test::BadScene kBad[] = {
    {"path and segments", "[path]\nkind = \"line\"\n[[segment]]\npath = { kind = \"line\" }\n", "path",
     ":1:1:", "not both"},
    {"neither path nor hold", "[[segment]]\ncaption = \"nothing\"\n", "segment[1]", ":1:1:", "hold = SECONDS"},
    {"path and hold", "[[segment]]\npath = { kind = \"line\" }\nhold = 2\n", "segment[1].hold", ":3:8:", "not both"},
    {"unknown key", "[[segment]]\nhold = 1\nwait = 2\n", "segment[1].wait", ":3:8:", "unknown key"},
    {"bad path value in segment 2", "[[segment]]\nhold = 1\n[[segment]]\npath = { kind = \"circle\", radius = -2 }\n",
     "segment[2].path.radius", ":4:36:", "> 0"},
    {"heading of a later plane segment",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\npath = { kind = \"line\", direction_vector = [0, 1, 0] }\n",
     "segment[2].path.direction_vector", ":4:44:", "tangent-continuous"},
    {"path kind off the surface", "[[segment]]\npath = { kind = \"parallel\" }\n", "segment[1].path.kind",
     ":2:17:", "leave the surface"},
    {"segments that do not meet on a sphere",
     "[surface]\nkind = \"sphere\"\nradius = 4\n[[segment]]\npath = { kind = \"meridian\", colatitude_start_deg = 30, "
     "colatitude_end_deg = 60 }\n[[segment]]\npath = { kind = \"parallel\", colatitude_deg = 50 }\n",
     "segment[2].path", ":7:8:", "must start where the previous segment ended"},
    {"duration and speed", "[[segment]]\npath = { kind = \"line\" }\nduration = 2\nspeed = 1\n", "segment[1].speed",
     ":4:9:", "not both"},
    {"negative hold", "[[segment]]\nhold = -1\n", "segment[1].hold", ":2:8:", "(0, 3600]"},
    {"duration of a hold", "[[segment]]\nhold = 1\nduration = 2\n[[segment]]\npath = { kind = \"line\" }\n",
     "segment[1].duration", ":3:12:", "applies to a motion"},
    {"unknown camera key", "[[segment]]\npath = { kind = \"line\" }\ncamera = { zoom = 2 }\n", "segment[1].camera.zoom",
     ":3:19:", "unknown key"},
    {"camera elevation", "[[segment]]\npath = { kind = \"line\" }\ncamera = { elevation_deg = 95 }\n",
     "segment[1].camera.elevation_deg", ":3:28:", "(-90, 90)"},
    {"camera follows and targets",
     "[[segment]]\npath = { kind = \"line\" }\ncamera = { follow = true, target = [0, 0, 0] }\n",
     "segment[1].camera.target", ":3:36:", "follow"},
    {"plate and segments", "[plate]\nradius = 2\n[[segment]]\npath = { kind = \"circle\" }\n", "plate",
     ":1:1:", "cannot be combined"},
    {"segment is not an array of tables", "segment = 3\n", "segment", ":1:11:", "[[segment]]"},
    {"only holds", "[[segment]]\nhold = 1\n[[segment]]\nhold = 2\n", "segment",
     ":1:1:", "at least one segment with a path"},
    {"expression in a segment's path", "[[segment]]\npath = { kind = \"uv\", u = \"t +* 2\" }\n", "segment[1].path.u",
     ":2:31:", "cannot parse"},
};

std::string storyboard() { return (sourceDir() / "scenes/storyboard.toml").string(); }

}  // namespace

TEST(StoryboardCli, MalformedSegmentsExitTwoNamingTheSegmentKeyAndPlaceAndWriteNothing) {
  for (const auto& c : kBad) rollspin::test::expectBadScene(c);
}

// The gallery storyboard: line 4, circle r = 3 (6π), hold, line 3.
TEST(StoryboardCli, TimelineRunsOnThroughTheSegmentsAndNamesEachRowsSegment) {
  const auto dir = freshTempDir("storyboard_timeline");
  const auto out = dir / "t.csv";
  const auto r = runRollspin({"timeline", storyboard(), "-o", out.string(), "--set", "timeline.samples=2001"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream csv(rollspin::test::readFile(out));
  std::string line;
  std::getline(csv, line);  // the header row first (RFC 4180); method, steps and error estimate: t.csv.json
  EXPECT_EQ(line.substr(line.size() - 13), "tau_g,segment");
  std::vector<int> seen;
  double s = -1.0, lastS = 0.0;
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const double rowS = std::stod(line.substr(0, line.find(',')));
    const int segment = std::stoi(line.substr(line.rfind(',') + 1));
    EXPECT_GT(rowS, s);
    s = lastS = rowS;
    if (seen.empty() || seen.back() != segment) seen.push_back(segment);
    // Rows of segment 1 lie on the line (s ≤ 4), of segment 4 past the circle.
    if (segment == 1) {
      EXPECT_LT(rowS, 4.0);
    } else if (segment == 2) {
      EXPECT_GE(rowS, 4.0);
    } else {
      EXPECT_GE(rowS, 4.0 + 6.0 * std::numbers::pi);
    }
  }
  EXPECT_EQ(rows, 2001);
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 4}));             // the hold (3) has no arc length
  EXPECT_NEAR(lastS, 7.0 + 6.0 * std::numbers::pi, 1e-12);  // s is cumulative
  const auto solved = runRollspin({"solve", storyboard(), "--json"});
  ASSERT_EQ(solved.exitCode, 0) << solved.err;
  EXPECT_NE(solved.out.find("\"length\": 25.849555921538759"), std::string::npos) << solved.out;
}

TEST(StoryboardCli, PrintShowsTheResolvedSegmentsAndReadsBack) {
  const auto dir = freshTempDir("storyboard_print");
  const auto first = runRollspin({"scene", storyboard(), "--print"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  for (const char* text :
       {"# segment 1: s 0 to 4 (length 4) in 3 s, 90 frames", "[[segment]]", "[segment.path]", "[segment.camera]",
        "hold = 2.5", "follow = true", "# segment 3: rests at s = 22.8496 for 2.5 s, 75 frames"})
    EXPECT_NE(first.out.find(text), std::string::npos) << text << "\n" << first.out;
  EXPECT_EQ(first.out.find("\n[path]"), std::string::npos) << "a storyboard has no [path]";
  // Later plane segments continue from the previous end: no direction printed.
  EXPECT_EQ(first.out.find("direction_vector = ["), std::string::npos);
  const auto printed = dir / "printed.toml";
  std::ofstream(printed) << first.out;
  const auto second = runRollspin({"scene", printed.string(), "--print"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_EQ(first.out.substr(first.out.find("\n\n")), second.out.substr(second.out.find("\n\n")));
}

// A segment's `duration = 10` must not read as the clip's: each segment's
// own key carries how long that segment really lasts and its s range, a
// segment without its own timing gets its real duration as a comment, and
// [animation]'s duration says it is the whole path's time at one speed, not
// the clip's. The printed TOML still reads back to the same scene.
TEST(StoryboardCli, PrintSaysHowLongEachSegmentReallyLasts) {
  const auto dir = freshTempDir("storyboard_durations");
  std::ofstream(dir / "story.toml") << "[animation]\nduration = 4\n"
                                    << "[[segment]]\nduration = 10\npath = { kind = \"line\", length = 2 }\n"
                                    << "[[segment]]\npath = { kind = \"line\", length = 6 }\n";
  const auto first = runRollspin({"scene", (dir / "story.toml").string(), "--print"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  // Segment 2 moves at 8 / 4 = 2 per second: 6 long, 3 s. The clip: 10 + 3 s
  // and animation.hold (0.5 s) at each end, 14 s: 15 + 300 + 90 + 15 frames at 30 fps.
  for (const char* text :
       {"duration = 10  # this segment lasts 10 s (s 0 to 2), not the clip",
        "# duration = 3 s: this segment (s 2 to 8) at the storyboard's speed",
        "duration = 4  # the whole path's time at one speed, not the clip's: segments without "
        "their own timing move at 2 per second; the clip lasts 14 s, 420 frames (15 opening, 390 in the "
        "segments, 15 closing)"})
    EXPECT_NE(first.out.find(text), std::string::npos) << text << "\n" << first.out;
  const auto printed = dir / "printed.toml";
  std::ofstream(printed) << first.out;
  const auto second = runRollspin({"scene", printed.string(), "--print"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_EQ(first.out.substr(first.out.find("\n\n")), second.out.substr(second.out.find("\n\n")));
}

TEST(StoryboardCli, ExtendsReplacesThePathOrTheSegmentsAsAWhole) {
  const auto dir = freshTempDir("storyboard_extends");
  const std::string scenes = (sourceDir() / "scenes").string();
  // A storyboard from the lollipop: its [path] gives way to the segments.
  std::ofstream(dir / "from_lollipop.toml") << "extends = \"" << scenes << "/lollipop.toml\"\n"
                                            << "[[segment]]\npath = { kind = \"line\", length = 2 }\n";
  // A child storyboard: its one segment replaces all four of the parent's.
  std::ofstream(dir / "short.toml")
      << "extends = \"" << storyboard() << "\"\n"
      << "[[segment]]\npath = { kind = \"circle\", radius = 2 }\ncaption = \"only this\"\n";
  // A child with a [path]: the parent's segments give way.
  std::ofstream(dir / "plain.toml") << "extends = \"" << storyboard() << "\"\n[path]\nkind = \"line\"\nlength = 5\n";
  const auto a = runRollspin({"scene", (dir / "from_lollipop.toml").string(), "--print"});
  ASSERT_EQ(a.exitCode, 0) << a.err;
  EXPECT_EQ(a.out.find("\n[path]"), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("length = 2"), std::string::npos) << a.out;
  const auto b = runRollspin({"scene", (dir / "short.toml").string(), "--print"});
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(b.out.find("# segment 2"), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("caption = \"only this\""), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("title = \"A rolling ball is a spin-1/2 in a field\""),
            std::string::npos);  // the rest is inherited
  const auto c = runRollspin({"solve", (dir / "plain.toml").string(), "--json"});
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_NE(c.out.find("\"length\": 5,"), std::string::npos) << c.out;
  // A bad key in the parent's segment still names the parent's file and line.
  std::ofstream(dir / "bad_parent.toml")
      << "[[segment]]\nhold = 1\n[[segment]]\npath = { kind = \"line\", length = 0 }\n";
  std::ofstream(dir / "child.toml") << "extends = \"bad_parent.toml\"\n[ball]\nradius = 2\n";
  const auto d = runRollspin({"solve", (dir / "child.toml").string()});
  EXPECT_EQ(d.exitCode, 2);
  EXPECT_NE(d.err.find("bad_parent.toml:4:"), std::string::npos) << d.err;
  EXPECT_NE(d.err.find("segment[2].path.length"), std::string::npos) << d.err;
}

// --set reaches into a segment by its number: "change one number, get a new video".
TEST(StoryboardCli, SetReachesIntoASegment) {
  const auto r = runRollspin({"solve", storyboard(), "--json", "--set", "segment[2].path.radius=4"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double length = 7.0 + 8.0 * std::numbers::pi;  // line 4, circle r = 4, line 3
  EXPECT_NE(r.out.find(fmt::format("\"length\": {:.17g}", length)), std::string::npos) << r.out;
  const auto printed = runRollspin({"scene", storyboard(), "--print", "--set", "segment[3].hold=1"});
  EXPECT_NE(printed.out.find("hold = 1\n"), std::string::npos) << printed.out;
  struct Bad {
    const char* arg;
    const char* message;
  };
  for (const Bad& b :
       {Bad{"segment[2].path.radius=-4", "segment[2].path.radius: expected a radius > 0"},
        Bad{"segment[7].caption=x", "the scene has 4 segment entries"}, Bad{"segment[0].caption=x", "counted from 1"},
        Bad{"segment[2].path.wobble=1", "segment[2].path.wobble: unknown key"}}) {
    const auto bad = runRollspin({"solve", storyboard(), "--set", b.arg});
    EXPECT_EQ(bad.exitCode, 2) << b.arg;
    EXPECT_NE(bad.err.find(std::string("--set ") + b.arg), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find(b.message), std::string::npos) << bad.err;
  }
}
