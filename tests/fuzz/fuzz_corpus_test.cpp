// Replays every fuzz corpus and fixed crash (tests/fuzz/corpus/TARGET/ and the files
// directly in tests/fuzz/crashes/TARGET/) through its harness in the normal build, so a
// regression of anything the fuzzers once found fails the ordinary test run.
#include "tests/fuzz/fuzz_targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace inkray {

// The replay's side of fuzz_targets.h: a broken oracle becomes an exception that
// the test reports with the file's name, instead of an abort that would hide it.
struct FuzzFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};
void fuzz_fail(const std::string& what) { throw FuzzFailure(what); }

namespace {

namespace fs = std::filesystem;
using Harness = int (*)(const std::uint8_t*, std::size_t);

const fs::path kFuzz = fs::path(INKRAY_SOURCE_DIR) / "tests" / "fuzz";

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> files;
  for (const char* folder : {"corpus", "crashes"}) {
    const fs::path dir = kFuzz / folder / target;
    if (!fs::is_directory(dir)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // a stable order makes a failure easy to repeat
  return files;
}

// Every target has inputs: one without would pass by replaying nothing.
void replay(const std::string& target, Harness harness) {
  const std::vector<fs::path> files = inputs_of(target);
  EXPECT_FALSE(files.empty()) << "no inputs for " << target;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    try {
      harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const FuzzFailure& e) {
      ADD_FAILURE() << file << ": " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": threw " << e.what();
    } catch (...) {
      ADD_FAILURE() << file << ": threw something that is not a std::exception";
    }
  }
  ::testing::Test::RecordProperty("inputs", static_cast<int>(files.size()));
}

TEST(FuzzCorpus, SceneReader) { replay("scene_reader", fuzz_scene_reader); }
TEST(FuzzCorpus, ObjLoader) { replay("obj_loader", fuzz_obj_loader); }
TEST(FuzzCorpus, ImageReader) { replay("image_reader", fuzz_image_reader); }
TEST(FuzzCorpus, GraphCompile) { replay("graph_compile", fuzz_graph_compile); }
TEST(FuzzCorpus, PartialReader) { replay("partial_reader", fuzz_partial_reader); }
TEST(FuzzCorpus, CheckpointReader) { replay("checkpoint_reader", fuzz_checkpoint_reader); }
TEST(FuzzCorpus, LineDecisionsReader) { replay("line_decisions_reader", fuzz_line_decisions_reader); }
TEST(FuzzCorpus, AnimationTracks) { replay("animation_tracks", fuzz_animation_tracks); }

}  // namespace
}  // namespace inkray
