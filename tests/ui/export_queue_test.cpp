// The editor's export queue and its dialog's checks, without a window: exports run one
// at a time in the order they were added, a cancelled one writes nothing and a queued
// one never starts; the dialog's form names a wrong extension, a missing folder and
// the files Start would replace.
#include "ui/model/export_queue.h"

#include "core/document/json_io.h"
#include "support/file_helpers.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using testing::ScratchFolder;
using testing::write_file;

ExportRequest quick_request(const fs::path& output) {
  const auto loaded = load_scene(fs::path(INKRAY_SOURCE_DIR) / "scenes" / "cornell.json");
  EXPECT_TRUE(loaded.scene);
  ExportRequest r;
  r.scene = loaded.scene ? *loaded.scene : SceneDesc{};
  r.scene.render.width = 24;
  r.scene.render.height = 16;
  r.output = output;
  r.spp = 3;
  r.threads = 1;
  return r;
}

// Polls as the editor does every frame, until nothing is queued or running; returns
// the ids in the order they finished and checks that no two ever ran at once.
std::vector<uint64_t> run_all(ExportQueue& queue) {
  std::vector<uint64_t> finished;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    for (uint64_t id : queue.poll()) finished.push_back(id);
    const auto running = std::count_if(queue.entries().begin(), queue.entries().end(),
                                       [](const ExportEntry& e) { return e.state == ExportState::running; });
    EXPECT_LE(running, 1);
    if (running == 0 && queue.queued() == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return finished;
}

TEST(ExportQueue, RunsOneAtATimeInOrder) {
  ScratchFolder dir;
  ExportQueue queue;
  const uint64_t a = queue.add(quick_request(dir / "a.png"), false);
  const uint64_t b = queue.add(quick_request(dir / "b.pfm"), true);
  const uint64_t c = queue.add(quick_request(dir / "c.exr"), false);
  EXPECT_EQ(queue.queued(), 3);
  EXPECT_EQ(queue.running(), nullptr);
  EXPECT_FALSE(queue.viewport_paused());
  queue.poll();
  ASSERT_NE(queue.running(), nullptr);
  EXPECT_EQ(queue.running()->id, a);
  EXPECT_TRUE(queue.viewport_paused());  // a did not ask to keep the viewport
  EXPECT_EQ(queue.queued(), 2);
  EXPECT_EQ(run_all(queue), (std::vector<uint64_t>{a, b, c}));
  for (const uint64_t id : {a, b, c}) {
    const ExportEntry* e = queue.find(id);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->state, ExportState::done) << e->error;
    ASSERT_EQ(e->written.size(), 1u);
    EXPECT_TRUE(fs::exists(e->written[0]));
    EXPECT_EQ(e->progress.spp, 3u);
    EXPECT_EQ(e->progress.phase, ExportPhase::finished);
  }
  EXPECT_FALSE(queue.viewport_paused());
  queue.clear_finished();
  EXPECT_TRUE(queue.entries().empty());
}

TEST(ExportQueue, ViewportPausesOnlyForExportsThatAskedIt) {
  ScratchFolder dir;
  ExportQueue queue;
  queue.add(quick_request(dir / "a.png"), true);
  queue.poll();
  ASSERT_NE(queue.running(), nullptr);
  EXPECT_FALSE(queue.viewport_paused());
  run_all(queue);
}

// A long export cancelled while it renders, one cancelled while it waits, and one
// after them that still runs.
TEST(ExportQueue, CancelledExportsWriteNothing) {
  ScratchFolder dir;
  ExportQueue queue;
  ExportRequest slow = quick_request(dir / "slow.png");
  slow.scene = testing::white_room_scene(800, 600);
  slow.spp = 4;
  const uint64_t running = queue.add(slow, false);
  const uint64_t waiting = queue.add(quick_request(dir / "waiting.png"), false);
  const uint64_t after = queue.add(quick_request(dir / "after.png"), false);
  queue.poll();
  ASSERT_NE(queue.running(), nullptr);
  EXPECT_EQ(queue.running()->id, running);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  queue.cancel(waiting);
  EXPECT_EQ(queue.find(waiting)->state, ExportState::cancelled);
  queue.cancel(running);
  EXPECT_EQ(run_all(queue), (std::vector<uint64_t>{running, after}));
  EXPECT_EQ(queue.find(running)->state, ExportState::cancelled);
  EXPECT_EQ(queue.find(after)->state, ExportState::done);
  EXPECT_TRUE(queue.find(running)->written.empty());
  EXPECT_FALSE(fs::exists(dir / "slow.png"));
  EXPECT_FALSE(fs::exists(dir / "waiting.png"));
  EXPECT_TRUE(fs::exists(dir / "after.png"));
}

TEST(ExportQueue, CancelAllStopsEverything) {
  ScratchFolder dir;
  ExportQueue queue;
  ExportRequest slow = quick_request(dir / "slow.png");
  slow.scene = testing::white_room_scene(800, 600);
  queue.add(slow, false);
  queue.add(quick_request(dir / "next.png"), false);
  queue.poll();
  queue.cancel_all();
  EXPECT_EQ(run_all(queue).size(), 1u);  // the running one; the queued one never started
  for (const ExportEntry& e : queue.entries()) EXPECT_EQ(e.state, ExportState::cancelled);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 0);
}

TEST(ExportQueue, AFailedExportIsReportedAndTheNextRuns) {
  ScratchFolder dir;
  ExportQueue queue;
  const uint64_t bad = queue.add(quick_request(dir / "no_folder" / "x.png"), false);
  const uint64_t good = queue.add(quick_request(dir / "good.png"), false);
  EXPECT_EQ(run_all(queue), (std::vector<uint64_t>{bad, good}));
  EXPECT_EQ(queue.find(bad)->state, ExportState::failed);
  EXPECT_NE(queue.find(bad)->error.find("x.png"), std::string::npos) << queue.find(bad)->error;
  EXPECT_EQ(queue.find(good)->state, ExportState::done);
}

TEST(ExportForm, DefaultPathIsTheScenesStemBesideIt) {
  EXPECT_EQ(default_export_path("/scenes/toon.json"), fs::path("/scenes/toon.png"));
  EXPECT_EQ(default_export_path({}), fs::current_path() / "render.png");
}

TEST(ExportForm, FormatComesFromTheExtension) {
  ScratchFolder dir;
  ExportForm form;
  const std::vector<std::pair<std::string, std::string>> formats = {
      {"a.png", "PNG"}, {"a.exr", "OpenEXR"}, {"a.pfm", "PFM"}};
  for (const auto& [name, format] : formats) {
    form.output = (dir / name).string();
    const ExportFormCheck c = check_export_form(form, {});
    EXPECT_EQ(c.error, "") << name;
    EXPECT_EQ(c.format.rfind(format, 0), 0u) << c.format;
  }
  for (const char* name : {"a.jpg", "a", "a.png.txt"}) {
    form.output = (dir / name).string();
    const ExportFormCheck c = check_export_form(form, {});
    EXPECT_EQ(c.format, "") << name;
    EXPECT_NE(c.error.find(name), std::string::npos) << c.error;
    EXPECT_NE(c.error.find(".png, .exr or .pfm"), std::string::npos) << c.error;
  }
}

TEST(ExportForm, RelativePathsAreFromTheScenesFolder) {
  ScratchFolder dir;
  ExportForm form;
  form.output = "out.exr";
  const ExportFormCheck c = check_export_form(form, dir / "scene.json");
  EXPECT_EQ(c.error, "");
  EXPECT_EQ(c.output, dir / "out.exr");
  form.output = "missing/out.png";
  const ExportFormCheck missing = check_export_form(form, dir / "scene.json");
  EXPECT_NE(missing.error.find((dir / "missing").string()), std::string::npos) << missing.error;
  EXPECT_NE(missing.error.find("no such folder"), std::string::npos) << missing.error;
  form.output = "";
  EXPECT_NE(check_export_form(form, dir / "scene.json").error, "");
}

TEST(ExportForm, ListsTheFilesStartWouldReplace) {
  ScratchFolder dir;
  ExportForm form;
  form.output = (dir / "out.png").string();
  form.aovs[size_t(Aov::albedo)] = true;
  form.aovs[size_t(Aov::depth)] = true;
  ExportFormCheck c = check_export_form(form, {});
  EXPECT_EQ(c.files, (std::vector<fs::path>{dir / "out.png", dir / "out_albedo.png", dir / "out_depth.png"}));
  EXPECT_TRUE(c.existing.empty());
  write_file(dir / "out_depth.png", "x");
  c = check_export_form(form, {});
  EXPECT_EQ(c.existing, (std::vector<fs::path>{dir / "out_depth.png"}));
  write_file(dir / "out.png", "x");
  EXPECT_EQ(check_export_form(form, {}).existing.size(), 2u);
  fs::create_directory(dir / "out_albedo.png");
  EXPECT_NE(check_export_form(form, {}).error.find("out_albedo.png is a folder"), std::string::npos);
  // Denoised, the raw image is one of them, and the request asks for denoising.
  fs::remove(dir / "out_albedo.png");
  form.denoise = true;
  c = check_export_form(form, {});
  EXPECT_EQ(c.files, (std::vector<fs::path>{dir / "out.png", dir / "out_raw.png", dir / "out_albedo.png",
                                            dir / "out_depth.png"}));
  EXPECT_TRUE(make_export_request(form, c, SceneDesc{}).denoise);
}

TEST(ExportForm, RefusesLimitsOutOfRange) {
  ScratchFolder dir;
  ExportForm form;
  form.output = (dir / "out.png").string();
  form.spp = 0;
  EXPECT_NE(check_export_form(form, {}).error.find("samples"), std::string::npos);
  form.spp = 16;
  form.noise_target = 1.5f;
  EXPECT_NE(check_export_form(form, {}).error.find("noise target"), std::string::npos);
  form.noise_target = 0.f;
  form.width = 20000;
  EXPECT_NE(check_export_form(form, {}).error.find("resolution"), std::string::npos);
}

TEST(ExportForm, RequestCarriesTheFormAndTheThreads) {
  ScratchFolder dir;
  ExportForm form;
  form.output = "x.exr";
  form.spp = 77;
  form.time_seconds = 12.f;
  form.noise_target = 0.02f;
  form.width = 640;
  form.height = 360;
  form.aovs[size_t(Aov::normal)] = true;
  const ExportFormCheck check = check_export_form(form, dir / "s.json");
  ASSERT_EQ(check.error, "");
  ExportRequest r = make_export_request(form, check, SceneDesc{});
  EXPECT_EQ(r.output, dir / "x.exr");
  EXPECT_EQ(r.spp, 77);
  EXPECT_DOUBLE_EQ(r.time_seconds, 12.0);
  EXPECT_NEAR(r.noise_target, 0.02, 1e-7);
  EXPECT_EQ(r.aovs, std::vector<Aov>{Aov::normal});
  EXPECT_EQ(export_resolution(r), std::make_pair(640, 360));
  EXPECT_EQ(r.threads, export_threads(false));
  form.keep_viewport = true;
  EXPECT_EQ(make_export_request(form, check, SceneDesc{}).threads, export_threads(true));
}

}  // namespace
}  // namespace inkray
