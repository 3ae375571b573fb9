// 325 mutated copies of the example scenes, each taken through the whole pipeline
// a user's file meets: read, write and read again, compile under a memory limit
// and a deadline, render. No input may crash, hang, throw or give a non-finite
// pixel; what the reader accepts must survive being written.
#include "core/film/resolve.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"

#include "tests/support/messages.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::joined;

// Every value's JSON pointer, containers included, so a mutation can hit any level.
void collect_pointers(const Json& j, const Json::json_pointer& at, std::vector<Json::json_pointer>& out) {
  out.push_back(at);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) collect_pointers(it.value(), at / it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collect_pointers(j[i], at / i, out);
  }
}

// Values that break assumptions: extremes of every range, wrong types, empties.
Json hostile_value(std::mt19937& rng) {
  static const std::vector<Json> values = {0,
                                           -1,
                                           1e-30,
                                           1e30,
                                           3.4e38,
                                           -3.4e38,
                                           1e9,
                                           -1e9,
                                           2147483647,
                                           -2147483648.0,
                                           0.5,
                                           64,
                                           1024,
                                           1e7,
                                           16384,
                                           "",
                                           "x",
                                           true,
                                           nullptr,
                                           Json::array(),
                                           Json::object(),
                                           Json::array({0, 0, 0}),
                                           Json::array({1e30, -1e30, 1e30}),
                                           Json::array({1, 2}),
                                           Json::object({{"type", "image"}, {"path", ""}}),
                                           Json::object({{"type", "checker"}})};
  return values[rng() % values.size()];
}

// A number pushed to where bugs live: zero, tiny, huge, negated, scaled.
Json nudged_number(double x, std::mt19937& rng) {
  switch (rng() % 6) {
    case 0:
      return 0;
    case 1:
      return x * 1e-6;
    case 2:
      return x * 1e3;
    case 3:
      return -x;
    case 4:
      return x + 1;
    default:
      return 1e-7;
  }
}

void mutate(Json& doc, std::mt19937& rng) {
  const int edits = 1 + int(rng() % 2);
  for (int e = 0; e < edits; ++e) {
    std::vector<Json::json_pointer> pointers;
    collect_pointers(doc, Json::json_pointer(), pointers);
    const Json::json_pointer at = pointers[rng() % pointers.size()];
    if (at.empty()) continue;
    Json& parent = doc[at.parent_pointer()];
    const unsigned kind = rng() % 8;
    if (kind == 0) {  // drop the value (a required key, a list element)
      if (parent.is_object()) {
        parent.erase(at.back());
      } else if (parent.is_array()) {
        parent.erase(std::stoul(at.back()));
      }
    } else if (kind == 1) {  // repeat a list element: duplicate names, twice the strokes
      if (parent.is_array()) parent.push_back(doc[at]);
    } else if (kind <= 5 && doc[at].is_number()) {
      doc[at] = nudged_number(doc[at].get<double>(), rng);
    } else {
      doc[at] = hostile_value(rng);
    }
  }
}

bool all_finite(const RgbImage& image) {
  return std::all_of(image.pixels.begin(), image.pixels.end(), [](const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
  });
}

TEST(MutatedScenes, NoInputCrashesHangsOrRendersNonFinite) {
  const fs::path dir = fs::path(INKRAY_SOURCE_DIR) / "scenes";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 13u);

  std::mt19937 rng(2026);
  int read = 0, compiled = 0, rendered = 0;
  const int per_file = (325 + int(files.size()) - 1) / int(files.size());
  for (const fs::path& file : files) {
    std::ifstream in(file);
    const Json original = Json::parse(in);
    for (int m = 0; m < per_file; ++m) {
      Json doc = original;
      mutate(doc, rng);
      const std::string text = doc.dump();
      SCOPED_TRACE(file.filename().string() + " mutation " + std::to_string(m) + ": " + text.substr(0, 400));
      SceneLoadResult loaded;
      ASSERT_NO_THROW(loaded = parse_scene(text, dir, "mutated.json"));
      ASSERT_EQ(loaded.scene.has_value(), loaded.errors.empty());
      if (!loaded) continue;
      ++read;
      // What was accepted is written and read back to the same document.
      const std::string written = scene_to_string(*loaded.scene);
      const SceneLoadResult again = parse_scene(written, dir, "rewritten.json");
      ASSERT_TRUE(again) << joined(again.errors);
      ASSERT_EQ(scene_to_string(*again.scene), written);

      SceneDesc desc = *loaded.scene;
      desc.render.width = 16;
      desc.render.height = 12;
      CompileOptions options;
      options.memory_limit = std::uint64_t(1) << 30;
      // A guard against a hang, not a timing: a mutation that explodes the work (a huge
      // count, a deep graph) is cut off here rather than by CTest's timeout. Generous, since
      // the sanitizer build on a loaded 2-core machine took over 10 s for strokes_100k.
      options.cancel = Cancel::at(Cancel::Clock::now() + std::chrono::seconds(120));
      CompileResult c;
      ASSERT_NO_THROW(c = compile_scene(desc, options));
      ASSERT_FALSE(c.cancelled) << "building took more than 120 s";
      if (!c.scene) continue;
      ++compiled;
      RenderSession session(1);
      session.set_scene(c.scene);
      render_batch(session, {1, 2.0});
      const RgbImage image = resolve_final(session.film(), *c.scene);
      ASSERT_TRUE(all_finite(image));
      ++rendered;
    }
  }
  std::printf("[ info ] %d mutated scenes: %d read, %d compiled, %d rendered\n", per_file * int(files.size()),
              read, compiled, rendered);
  // The mutations must leave enough scenes valid to exercise compiling and rendering.
  EXPECT_GT(rendered, 60);
}

}  // namespace
}  // namespace inkray
