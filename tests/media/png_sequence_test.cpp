// PngSequenceWriter: frames staged beside the folder and moved in on
// finish(); a whole-clip render removes our stale frames (exact naming only)
// and nothing else; a part keeps the other frames; an interrupted render goes
// to FOLDER.partial/ and leaves FOLDER/ alone; an error leaves nothing new.
#include <gtest/gtest.h>

#include <fstream>

#include "media/png_sequence.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// An earlier render of 8 frames plus files that are not ours.
fs::path earlierRender(const std::string& name) {
  const fs::path dir = test::freshTempDir(name);
  fs::create_directories(dir / "frames");
  for (int k = 0; k < 8; ++k) std::ofstream(PngSequenceWriter::framePath(dir / "frames", k)) << "old";
  for (const char* foreign : {"notes.txt", "frame_9.png", "frame_000010.png", "frame_00011.png.bak", "frame_0001x.png"})
    std::ofstream(dir / "frames" / foreign) << "keep";
  return dir;
}

const std::vector<std::string> kForeign{"frame_000010.png", "frame_00011.png.bak", "frame_0001x.png", "frame_9.png",
                                        "notes.txt"};

std::vector<std::string> withForeign(std::vector<std::string> frames) {
  frames.insert(frames.end(), kForeign.begin(), kForeign.end());
  std::sort(frames.begin(), frames.end());
  return frames;
}

void writeFrames(PngSequenceWriter& w, int count) {
  Image image(4, 2);
  for (int k = 0; k < count; ++k) w.write(image.view());
}

TEST(PngSequence, FrameIndexAcceptsExactlyOurNames) {
  EXPECT_EQ(PngSequenceWriter::frameIndex("frame_00042.png"), 42);
  EXPECT_EQ(PngSequenceWriter::frameIndex("frame_123456.png"), 123456);
  for (const char* other : {"frame_42.png", "frame_000042.png", "frame_00042.PNG", "frame_00042.png.bak", "frame_.png",
                            "xframe_00042.png", "frame_0004a.png", "frame_-0042.png"})
    EXPECT_EQ(PngSequenceWriter::frameIndex(other), -1) << other;
}

TEST(PngSequence, AWholeClipReplacesTheFramesAndRemovesOnlyOurStaleOnes) {
  const fs::path dir = earlierRender("png_whole");
  {
    PngSequenceWriter w(dir / "frames", 0, PngChannels::Rgb, PngSequenceScope::WholeClip);
    writeFrames(w, 5);
    EXPECT_EQ(test::readFile(dir / "frames/frame_00000.png"), "old") << "nothing moves before the render completes";
    EXPECT_EQ(w.finish(), dir / "frames");
  }
  EXPECT_EQ(filesIn(dir / "frames"), withForeign({"frame_00000.png", "frame_00001.png", "frame_00002.png",
                                                  "frame_00003.png", "frame_00004.png"}));
  EXPECT_NE(test::readFile(dir / "frames/frame_00004.png"), "old");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"frames"}) << "no staging folder left";
}

TEST(PngSequence, APartReplacesItsFramesOnlyAndKeepsTheOthers) {
  const fs::path dir = earlierRender("png_part");
  {
    PngSequenceWriter w(dir / "frames/", 3, PngChannels::Rgb, PngSequenceScope::Part);
    writeFrames(w, 2);
    w.finish();
  }
  std::vector<std::string> all;
  for (int k = 0; k < 8; ++k) all.push_back(PngSequenceWriter::framePath("", k).string());
  EXPECT_EQ(filesIn(dir / "frames"), withForeign(all));
  for (int k = 0; k < 8; ++k)
    EXPECT_EQ(test::readFile(PngSequenceWriter::framePath(dir / "frames", k)) == "old", k < 3 || k > 4) << k;
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"frames"});
}

TEST(PngSequence, AnInterruptedRenderGoesToPartialAndLeavesTheFolderAlone) {
  const fs::path dir = earlierRender("png_interrupted");
  fs::create_directories(dir / "frames.partial");
  std::ofstream(dir / "frames.partial/frame_00007.png") << "older partial";
  std::ofstream(dir / "frames.partial/readme") << "keep";
  {
    PngSequenceWriter w(dir / "frames", 0, PngChannels::Rgb, PngSequenceScope::WholeClip);
    writeFrames(w, 2);
    EXPECT_EQ(w.finishPartial(), dir / "frames.partial");
  }
  std::vector<std::string> old;
  for (int k = 0; k < 8; ++k) old.push_back(PngSequenceWriter::framePath("", k).string());
  EXPECT_EQ(filesIn(dir / "frames"), withForeign(old));
  for (int k = 0; k < 8; ++k) EXPECT_EQ(test::readFile(PngSequenceWriter::framePath(dir / "frames", k)), "old");
  EXPECT_EQ(filesIn(dir / "frames.partial"),
            (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "readme"}));
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"frames", "frames.partial"}));
}

TEST(PngSequence, NoFramesOrAnErrorLeaveNothingNew) {
  const fs::path dir = earlierRender("png_nothing");
  {
    PngSequenceWriter w(dir / "frames", 0, PngChannels::Rgb, PngSequenceScope::WholeClip);
    EXPECT_TRUE(w.finishPartial().empty());
  }
  {
    PngSequenceWriter w(dir / "frames", 0, PngChannels::Rgb, PngSequenceScope::WholeClip);
    writeFrames(w, 3);  // then destroyed unfinished, as after an exception
  }
  {
    PngSequenceWriter w(dir / "fresh", 0, PngChannels::Rgb, PngSequenceScope::WholeClip);
    writeFrames(w, 1);
  }
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"frames"});
  for (int k = 0; k < 8; ++k) EXPECT_EQ(test::readFile(PngSequenceWriter::framePath(dir / "frames", k)), "old");
}

}  // namespace
}  // namespace rollspin::media
