// inkray-render --checkpoint when the checkpoint cannot be written: the render goes on and
// its image is written, but the run fails, naming the checkpoint file and the cause.
#include "core/image/image_io.h"
#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using testing::ScratchFolder;

// The Cornell box, tiny, checkpointed after every pass, written to `output`.
std::string render_checkpointed(const std::string& extra, const fs::path& output, int* exit_code) {
  return testing::run_command(
      std::string(INKRAY_BINARY_DIR) + "/bin/inkray-render " + INKRAY_SOURCE_DIR +
          "/scenes/cornell.json --width 16 --height 16 --spp 8 -q --checkpoint 0.000001" + extra + " -o " +
          output.string(),
      exit_code);
}

TEST(CheckpointError, AFailedCheckpointFailsTheRunButTheImageIsWritten) {
  ScratchFolder dir;
  const fs::path checkpoint = dir / "still.png.checkpoint.exr";
  fs::create_directories(checkpoint / "in the way");  // a folder where the checkpoint goes
  int exit_code = -1;
  const std::string output = render_checkpointed("", dir / "still.png", &exit_code);
  EXPECT_EQ(exit_code, 1) << output;
  EXPECT_NE(output.find("checkpoint " + checkpoint.string() + " could not be written"), std::string::npos)
      << output;
  EXPECT_NE(output.find("Is a directory"), std::string::npos) << output;
  EXPECT_NE(output.find("the render completed and its files were written"), std::string::npos) << output;
  RgbImage image;
  std::string error;
  ASSERT_TRUE(read_image(dir / "still.png", true, &image, &error)) << error;
  EXPECT_EQ(image.width, 16);
}

TEST(CheckpointError, LaterFramesStillRender) {
  ScratchFolder dir;
  fs::create_directories(dir / "f1.png.checkpoint.exr" / "in the way");  // frame 1's checkpoint only
  int exit_code = -1;
  const std::string output = render_checkpointed(" --frames 1-2", dir / "f#.png", &exit_code);
  EXPECT_EQ(exit_code, 1) << output;
  EXPECT_NE(output.find("frame 1: checkpoint " + (dir / "f1.png.checkpoint.exr").string()), std::string::npos)
      << output;
  EXPECT_TRUE(fs::exists(dir / "f1.png"));
  EXPECT_TRUE(fs::exists(dir / "f2.png"));
  EXPECT_FALSE(fs::exists(dir / "f2.png.checkpoint.exr"));
}

TEST(CheckpointError, CheckpointsThatCanBeWrittenKeepExitZero) {
  ScratchFolder dir;
  int exit_code = -1;
  const std::string output = render_checkpointed("", dir / "still.png", &exit_code);
  EXPECT_EQ(exit_code, 0) << output;
  EXPECT_EQ(dir.entries(),
            std::vector<std::string>{"still.png"});  // the checkpoint went with the render's end
}

}  // namespace
}  // namespace inkray
