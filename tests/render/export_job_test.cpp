// The editor's background export: writes the image and its AOVs at the scene's
// resolution or an override, renders the same pixels on any number of threads, reports
// progress figures that only move forward, stops at a noise target, and names the file
// it could not write.
#include "core/render/export_job.h"
#include "core/document/json_io.h"
#include "core/image/image_io.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <chrono>
#include <filesystem>
#include <thread>

namespace inkray {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("inkray_export_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

SceneDesc example(const std::string& name, int width, int height) {
  const auto loaded = load_scene(fs::path(INKRAY_SOURCE_DIR) / "scenes" / name);
  EXPECT_TRUE(loaded.scene) << name;
  SceneDesc d = loaded.scene ? *loaded.scene : SceneDesc{};
  d.render.width = width;
  d.render.height = height;
  return d;
}

// `scene` rendered at `spp` samples on `threads` threads and written to `output`.
ExportRequest request(SceneDesc scene, fs::path output, int spp, int threads) {
  ExportRequest r;
  r.scene = std::move(scene);
  r.output = std::move(output);
  r.spp = spp;
  r.threads = threads;
  return r;
}

SceneDesc tiny_cornell() { return example("cornell.json", 24, 16); }

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
    ExportRequest r = request(tiny_cornell(), dir / name, 4, 2);
    r.aovs = {Aov::albedo};
    ExportJob job(r);
    wait_done(job);
    EXPECT_EQ(job.error(), "");
    EXPECT_FLOAT_EQ(job.progress().fraction, 1.f);
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
        ASSERT_EQ(LoadEXR(&rgba, &w, &h, file.string().c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
        free(rgba);
        EXPECT_EQ(w, 24);
        EXPECT_EQ(h, 16);
      }
    }
  }
  fs::remove_all(dir);
}

// Denoised from the export dialog: the image denoised, the raw one beside it, and the
// denoised estimate in the progress figures.
TEST(ExportJob, DenoiseWritesTheDenoisedAndTheRawImage) {
  const fs::path dir = fresh_dir("denoise");
  ExportRequest r = request(example("cornell_outlines.json", 48, 32), dir / "out.pfm", 8, 2);
  r.denoise = true;
  ExportJob job(r);
  wait_done(job);
  EXPECT_EQ(job.error(), "");
  ASSERT_EQ(job.written().size(), 2u);
  RgbImage denoised, raw;
  std::string error;
  ASSERT_TRUE(read_pfm(dir / "out.pfm", &denoised, &error)) << error;
  ASSERT_TRUE(read_pfm(dir / "out_raw.pfm", &raw, &error)) << error;
  EXPECT_NE(denoised.pixels, raw.pixels);
  EXPECT_GT(job.progress().denoised_error, 0.0);
  EXPECT_LT(job.progress().denoised_error, job.progress().relative_error);
  fs::remove_all(dir);
}

TEST(ExportJob, UnwritablePathReportsTheFile) {
  const fs::path dir = fresh_dir("bad");
  ExportRequest r = request(tiny_cornell(), dir / "missing_folder" / "out.png", 1, 1);
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
  ExportRequest r = request(tiny_cornell(), dir / "out.png", 1, 1);
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
  ExportJob job(request(d, dir / "room.png", 4, 1));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  job.cancel();
  wait_done(job);
  EXPECT_EQ(job.error(), "cancelled");
  EXPECT_TRUE(job.written().empty());
  EXPECT_EQ(job.progress().phase, ExportPhase::finished);
  EXPECT_LT(job.progress().fraction, 1.f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 0);  // not even a temporary
  fs::remove_all(dir);
}

RgbImage read_back(const fs::path& pfm) {
  RgbImage img;
  std::string error;
  EXPECT_TRUE(read_pfm(pfm, &img, &error)) << error;
  return img;
}

// Rendering does not depend on the thread count (tests/render/determinism_test.cpp), so
// an export on every core writes exactly the pixels of one on a single thread; outlines
// and AOVs included.
TEST(ExportJob, AllThreadsWriteTheSameImageAsOne) {
  const fs::path dir = fresh_dir("threads");
  for (const char* scene : {"cornell.json", "toon.json"}) {
    SCOPED_TRACE(scene);
    std::vector<RgbImage> images, albedos;
    for (int threads : {1, 2, 0}) {
      ExportRequest r =
          request(example(scene, 48, 32), dir / ("t" + std::to_string(threads) + ".pfm"), 6, threads);
      r.aovs = {Aov::albedo};
      ExportJob job(r);
      wait_done(job);
      ASSERT_EQ(job.error(), "");
      EXPECT_EQ(job.progress().threads,
                threads == 0 ? export_threads(false) : std::min(threads, export_threads(false)));
      images.push_back(read_back(r.output));
      albedos.push_back(read_back(ExportJob::aov_path(r.output, Aov::albedo)));
    }
    ASSERT_EQ(images[0].pixels.size(), size_t(48 * 32));
    for (size_t i = 1; i < images.size(); ++i) {
      EXPECT_TRUE(images[i].pixels == images[0].pixels) << "thread setting " << i;
      EXPECT_TRUE(albedos[i].pixels == albedos[0].pixels) << "thread setting " << i;
    }
  }
  fs::remove_all(dir);
}

TEST(ExportJob, ThreadsForTheViewportLeaveItOne) {
  EXPECT_GE(export_threads(false), 1);
  EXPECT_EQ(export_threads(true), std::max(1, export_threads(false) - 1));
}

// Read while the job runs, as the UI does: samples, elapsed time and the bar only move
// forward, stay within their targets, and end at the target; the time estimate is
// never beyond the time limit.
TEST(ExportJob, ProgressFiguresMoveForwardAndEndAtTheTarget) {
  const fs::path dir = fresh_dir("progress");
  ExportRequest r = request(example("cornell.json", 64, 48), dir / "out.png", 40, 2);
  r.time_seconds = 600.0;
  ExportJob job(r);
  ExportProgress last;
  int reads = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!job.done() && std::chrono::steady_clock::now() < deadline) {
    const ExportProgress p = job.progress();
    ++reads;
    EXPECT_GE(p.spp, last.spp);
    EXPECT_LE(p.spp, 40u);
    EXPECT_GE(p.elapsed_seconds, last.elapsed_seconds);
    EXPECT_GE(p.render_seconds, last.render_seconds);
    EXPECT_LE(p.render_seconds, p.elapsed_seconds);
    EXPECT_GE(p.fraction, last.fraction);
    EXPECT_LE(p.fraction, 1.f);
    EXPECT_GE(p.relative_error, 0.0);
    EXPECT_LE(p.eta_seconds, r.time_seconds);
    if (p.spp > 0) {
      EXPECT_GE(p.eta_seconds, 0.0);
    }
    if (p.phase == ExportPhase::rendering) {
      EXPECT_EQ(p.spp_target, 40u);
      EXPECT_EQ(p.width, 64);
      EXPECT_EQ(p.height, 48);
      EXPECT_EQ(p.threads, std::min(2, export_threads(false)));
    }
    last = p;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  wait_done(job);
  ASSERT_EQ(job.error(), "");
  const ExportProgress end = job.progress();
  EXPECT_EQ(end.phase, ExportPhase::finished);
  EXPECT_EQ(end.spp, 40u);
  EXPECT_FLOAT_EQ(end.fraction, 1.f);
  EXPECT_GT(end.relative_error, 0.0);
  EXPECT_GE(end.elapsed_seconds, last.elapsed_seconds);
  EXPECT_EQ(job.progress().elapsed_seconds, end.elapsed_seconds);  // the clock stops at the end
  EXPECT_GT(reads, 0);
  fs::remove_all(dir);
}

// A generous sample cap and a noise target: the export stops as soon as the estimate
// is below the target, long before the cap.
TEST(ExportJob, StopsAtTheNoiseTarget) {
  const fs::path dir = fresh_dir("noise");
  ExportRequest r = request(example("toon.json", 48, 32), dir / "out.pfm", 1 << 20,
                            2);  // flat bands: a few dozen samples reach 2%
  r.noise_target = 0.02;
  ExportJob job(r);
  wait_done(job);
  ASSERT_EQ(job.error(), "");
  const ExportProgress p = job.progress();
  EXPECT_GE(p.spp, 4u);
  EXPECT_LT(p.spp, uint32_t(1 << 20));
  EXPECT_GT(p.relative_error, 0.0);
  EXPECT_LE(p.relative_error, 0.02);
  EXPECT_FLOAT_EQ(p.fraction, 1.f);
  EXPECT_TRUE(fs::exists(r.output));
  fs::remove_all(dir);
}

TEST(ExportJob, ResolutionOverrideKeepsTheAspectUnlessBothAreGiven) {
  ExportRequest r;
  r.scene = tiny_cornell();  // 24 x 16
  EXPECT_EQ(export_resolution(r), std::make_pair(24, 16));
  r.width = 60;
  EXPECT_EQ(export_resolution(r), std::make_pair(60, 40));
  r.width = 0;
  r.height = 8;
  EXPECT_EQ(export_resolution(r), std::make_pair(12, 8));
  r.width = 30;
  r.height = 10;
  EXPECT_EQ(export_resolution(r), std::make_pair(30, 10));
  r.width = 100000;
  EXPECT_EQ(export_resolution(r), std::make_pair(16384, 10));

  const fs::path dir = fresh_dir("resolution");
  r.output = dir / "out.png";
  r.spp = 2;
  r.width = 36;
  r.height = 0;
  r.aovs = {Aov::depth};
  ExportJob job(r);
  wait_done(job);
  ASSERT_EQ(job.error(), "");
  for (const fs::path& file : {r.output, ExportJob::aov_path(r.output, Aov::depth)}) {
    RgbImage img;
    std::string error;
    ASSERT_TRUE(read_image(file, true, &img, &error)) << error;
    EXPECT_EQ(img.width, 36);
    EXPECT_EQ(img.height, 24);
  }
  EXPECT_EQ(r.scene.render.width, 24);  // the request's document is left alone
  fs::remove_all(dir);
}

}  // namespace
}  // namespace inkray
