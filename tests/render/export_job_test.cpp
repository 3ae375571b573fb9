// The editor's background export: writes the image and its AOVs at the scene's
// resolution, reports progress to done, and names the file it could not write.
#include "core/render/export_job.h"
#include "core/image/image_io.h"
#include "core/document/json_io.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <chrono>
#include <filesystem>
#include <thread>

namespace inkray {
namespace {

namespace fs = std::filesystem;

SceneDesc tiny_cornell() {
  const auto loaded = load_scene(fs::path(INKRAY_SOURCE_DIR) / "scenes" / "cornell.json");
  EXPECT_TRUE(loaded.scene);
  SceneDesc d = loaded.scene ? *loaded.scene : SceneDesc{};
  d.render.width = 24;
  d.render.height = 16;
  return d;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("inkray_export_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void wait_done(const ExportJob& job) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!job.done() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(job.done());
}

TEST(ExportJob, WritesPngAndExrWithAovsAtSceneSize) {
  const fs::path dir = fresh_dir("ok");
  for (const char* name : {"out.png", "out.exr"}) {
    SCOPED_TRACE(name);
    ExportRequest r;
    r.scene = tiny_cornell();
    r.output = dir / name;
    r.spp = 4;
    r.threads = 2;
    r.aovs = {Aov::albedo};
    ExportJob job(r);
    wait_done(job);
    EXPECT_EQ(job.error(), "");
    EXPECT_FLOAT_EQ(job.progress(), 1.f);
    const fs::path aov = ExportJob::aov_path(r.output, Aov::albedo);
    EXPECT_EQ(aov.filename().string(), std::string("out_albedo") + r.output.extension().string());
    ASSERT_EQ(job.written().size(), 2u);
    for (const fs::path& file : {r.output, aov}) {
      ASSERT_TRUE(fs::exists(file)) << file;
      if (r.output.extension() == ".png") {
        RgbImage img;
        std::string error;
        ASSERT_TRUE(read_image(file, true, &img, &error)) << error;
        EXPECT_EQ(img.width, 24);
        EXPECT_EQ(img.height, 16);
      } else {
        float* rgba = nullptr;
        int w = 0, h = 0;
        const char* err = nullptr;
        ASSERT_EQ(LoadEXR(&rgba, &w, &h, file.string().c_str(), &err), TINYEXR_SUCCESS)
            << (err ? err : "");
        free(rgba);
        EXPECT_EQ(w, 24);
        EXPECT_EQ(h, 16);
      }
    }
  }
  fs::remove_all(dir);
}

TEST(ExportJob, UnwritablePathReportsTheFile) {
  const fs::path dir = fresh_dir("bad");
  ExportRequest r;
  r.scene = tiny_cornell();
  r.output = dir / "missing_folder" / "out.png";
  r.spp = 1;
  r.threads = 1;
  ExportJob job(r);
  wait_done(job);
  EXPECT_NE(job.error().find(r.output.string()), std::string::npos) << job.error();
  EXPECT_TRUE(job.written().empty());
  fs::remove_all(dir);
}

// The image and its AOVs are written together: an AOV that cannot be written means no
// image either, found before rendering.
TEST(ExportJob, AFailedAovLeavesNoImage) {
  const fs::path dir = fresh_dir("aov");
  ExportRequest r;
  r.scene = tiny_cornell();
  r.output = dir / "out.png";
  r.spp = 1;
  r.threads = 1;
  r.aovs = {Aov::albedo, Aov::depth};
  const fs::path depth = ExportJob::aov_path(r.output, Aov::depth);
  fs::create_directory(depth);  // a folder where the depth AOV should go
  ExportJob job(r);
  wait_done(job);
  EXPECT_NE(job.error().find(depth.string()), std::string::npos) << job.error();
  EXPECT_TRUE(job.written().empty());
  EXPECT_FALSE(fs::exists(r.output));
  EXPECT_FALSE(fs::exists(ExportJob::aov_path(r.output, Aov::albedo)));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 1);  // the folder only, no temporaries
  fs::remove_all(dir);
}

// One pass of a closed white room at 1024 bounces and 800 x 600 takes minutes on one
// thread: Cancel must stop the pass in flight, not wait for its end (wait_done gives
// up after 60 s), and write nothing.
TEST(ExportJob, CancelStopsThePassInFlight) {
  const fs::path dir = fresh_dir("cancel");
  const SceneDesc d = testing::white_room_scene(800, 600);
  ExportRequest request;
  request.scene = d;
  request.output = dir / "room.png";
  request.spp = 4;
  request.threads = 1;
  ExportJob job(request);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  job.cancel();
  wait_done(job);
  EXPECT_EQ(job.error(), "cancelled");
  EXPECT_FALSE(fs::exists(dir / "room.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace inkray
