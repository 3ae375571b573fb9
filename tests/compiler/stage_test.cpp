// The stage table drives every edit: for every parameter of the example scenes, a
// change to it alone is reported as its stage, runs only that stage's work in the
// compiler, reads no file, and renders exactly as a compile from scratch of the
// edited document.
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "core/film/resolve.h"
#include "core/render/batch_render.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace inkray {
namespace {

const std::filesystem::path kScenes = INKRAY_SOURCE_DIR "/scenes";

// Changes the target-th parameter met while walking a document, as a slider or a
// checkbox would, and notes its stage. Names, paths and references are left
// alone: they are not values an edit nudges.
struct Nudge {
  int target = 0;
  int index = 0;
  bool changed = false;
  Stage stage = Stage::inherit;
  std::string name;
  Stage section = Stage::inherit;

  template <class T>
  void operator()(const Param& p, T& field) {
    const Stage s = p.stage == Stage::inherit ? section : p.stage;
    if constexpr (ParamGroup<T>) {
      const Stage outer = std::exchange(section, s);
      visit_params(field, *this);
      section = outer;
    } else if constexpr (std::is_same_v<T, std::vector<GraphNodeDesc>>) {
      // Every parameter of every node of a graph is one more edit to try.
      const Stage outer = std::exchange(section, s);
      for (GraphNodeDesc& node : field) std::visit([&](auto& n) { visit_params(n, *this); }, node.data);
      section = outer;
    } else if constexpr (requires {
                           field.front();
                           requires ParamGroup<typename T::value_type>;
                         }) {
      const Stage outer = std::exchange(section, s);
      for (auto& item : field) visit_params(item, *this);
      section = outer;
    } else {
      if (index++ != target) return;
      changed = nudge(p, field);
      stage = s;
      name = std::string(p.name);
    }
  }

  static float step(const Param& p, float v) {
    const float up = v + 0.05f + 0.1f * std::abs(v);
    return double(up) <= p.max ? up : std::max(float(p.min), v - 0.05f - 0.1f * std::abs(v));
  }
  bool nudge(const Param& p, float& v) {
    const float before = v;
    v = step(p, v);
    return v != before;
  }
  bool nudge(const Param& p, int& v) {
    const int before = v;
    v = double(v) + 1 <= p.max ? v + 1 : v - 1;
    if (p.kind == ParamKind::choice) v = int(double(before + 1) <= p.max ? before + 1 : 0);
    return v != before && double(v) >= p.min;
  }
  bool nudge(const Param&, bool& v) {
    v = !v;
    return true;
  }
  bool nudge(const Param& p, Vec3& v) {
    if (p.kind == ParamKind::direction) {
      v += Vec3(0.2f * glm::length(v) + 0.1f, 0.f, 0.f);
      return true;
    }
    const float before = v.x;
    v.x = step(p, v.x);
    return v.x != before;
  }
  bool nudge(const Param&, std::string&) { return false; }
  bool nudge(const Param& p, ColorInput& c) {
    if (auto* color = std::get_if<Color>(&c)) return nudge(p, *color);
    return false;
  }
  bool nudge(const Param& p, std::vector<Color>& list) { return !list.empty() && nudge(p, list.front()); }
  template <class E>
  requires std::is_enum_v<E>
  bool nudge(const Param& p, E& e) {
    int v = int(e);
    const bool changed = nudge(p, v);
    e = E(v);
    return changed;
  }

  template <class Desc>
  void walk(Desc& d, Stage s) {
    section = s;
    if constexpr (requires { d.index(); }) {
      std::visit([&](auto& alternative) { walk(alternative, s); }, d);
    } else {
      visit_params(d, *this);
    }
  }
  void walk(SceneDesc& d) {
    walk(d.camera, Stage::camera);
    walk(d.render, Stage::inherit);
    walk(d.outlines, Stage::inherit);
    walk(d.environment, Stage::light);
    for (MaterialDesc& m : d.materials) {
      walk(m.data, Stage::material);
      walk(m.lines, Stage::material);
    }
    for (ObjectDesc& o : d.objects) {
      walk(o, Stage::object);
      walk(o.shape, Stage::geometry);
      section = Stage::object;
      (*this)(vector("translate", ""), o.transform.translate);
    }
    for (LightDesc& l : d.lights) walk(l.data, Stage::light);
    for (StrokeEmitterDesc& e : d.strokes) walk(e, Stage::strokes);
  }
};

CompileCounters since(const CompileCounters& after, const CompileCounters& before) {
  CompileCounters d;
  d.compiles = after.compiles - before.compiles;
  d.checks = after.checks - before.checks;
  d.material_tables = after.material_tables - before.material_tables;
  d.materials = after.materials - before.materials;
  d.light_tables = after.light_tables - before.light_tables;
  d.top_levels = after.top_levels - before.top_levels;
  d.shape_bvhs = after.shape_bvhs - before.shape_bvhs;
  d.placements = after.placements - before.placements;
  d.stroke_sets = after.stroke_sets - before.stroke_sets;
  d.stroke_paints = after.stroke_paints - before.stroke_paints;
  d.files_read = after.files_read - before.files_read;
  return d;
}

// What each stage may build; anything else it runs is a failure.
void expect_only_stage_work(Stage stage, const CompileCounters& d, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(d.compiles, 1u);
  EXPECT_EQ(d.files_read, 0u) << "an edit read a file";
  const bool world = stage >= Stage::material;
  if (!world) {
    EXPECT_EQ(d.material_tables + d.light_tables + d.top_levels + d.shape_bvhs + d.placements +
                  d.stroke_sets + d.stroke_paints,
              0u)
        << "a view-only edit rebuilt part of the world";
    return;
  }
  EXPECT_EQ(d.material_tables, stage == Stage::material ? 1u : 0u);
  EXPECT_EQ(d.materials, stage == Stage::material ? 1u : 0u) << "a material edit compiles that material only";
  EXPECT_EQ(d.light_tables, 1u);
  if (stage == Stage::material || stage == Stage::light) {
    EXPECT_EQ(d.shape_bvhs, 0u);
    EXPECT_EQ(d.placements, 0u);
    EXPECT_EQ(d.stroke_sets, 0u);
  }
  if (stage == Stage::light) {
    EXPECT_EQ(d.top_levels, 0u);
    EXPECT_EQ(d.stroke_paints, 0u);
  }
  if (stage == Stage::material) {
    EXPECT_EQ(d.top_levels, d.stroke_paints > 0 ? 1u : 0u);
  }
  if (stage == Stage::object) {
    EXPECT_LE(d.shape_bvhs, 1u + d.stroke_sets) << "only a sphere's one-primitive BVH holds its transform";
  }
  if (stage == Stage::strokes) {
    EXPECT_LE(d.stroke_sets, 1u);
    EXPECT_LE(d.shape_bvhs, 1u);
  }
}

// Sections whose parameters differ in stage name each one's: a parameter added there
// without a stage would silently take the section's default.
struct ExplicitStages {
  std::vector<std::string> missing;
  std::string prefix;
  template <class T>
  void operator()(const Param& p, T& field) {
    if constexpr (ParamGroup<T>) {
      const std::string outer = std::exchange(prefix, prefix + std::string(p.name) + ".");
      visit_params(field, *this);
      prefix = outer;
    } else if (p.stage == Stage::inherit) {
      missing.push_back(prefix + std::string(p.name));
    }
  }
};

TEST(StageSections, MixedSectionsNameEveryParametersStage) {
  SceneDesc d;
  ExplicitStages render{{}, "render."};
  visit_params(d.render, render);
  ExplicitStages outlines{{}, "outlines."};
  visit_params(d.outlines, outlines);
  EXPECT_TRUE(render.missing.empty()) << render.missing.front();
  EXPECT_TRUE(outlines.missing.empty()) << outlines.missing.front();
}

class StageTable : public ::testing::TestWithParam<std::string> {};

TEST_P(StageTable, EveryParameterRunsItsStageOnly) {
  const std::filesystem::path file = kScenes / GetParam();
  SceneLoadResult loaded = load_scene(file);
  ASSERT_TRUE(loaded.scene) << (loaded.errors.empty() ? "" : loaded.errors.front());
  SceneDesc original = *loaded.scene;
  original.render.width = 32;
  original.render.height = 24;
  for (StrokeEmitterDesc& e : original.strokes)
    e.count = std::min(e.count, 300);  // the test's time, not its reach

  SceneCompiler compiler;
  ASSERT_TRUE(compiler.compile(original).scene);
  int tested = 0;
  for (int target = 0;; ++target) {
    SceneDesc edited = original;
    Nudge nudge;
    nudge.target = target;
    nudge.walk(edited);
    if (target >= nudge.index) break;  // walked past the last parameter
    if (!nudge.changed) continue;
    const std::string what = GetParam() + ": parameter " + std::to_string(target) + " \"" + nudge.name + "\"";
    const CompileResult fresh = compile_scene(edited);
    ASSERT_TRUE(compiler.compile(original).scene) << what;
    const CompileCounters before = compiler.counters();
    const CompileResult incremental = compiler.compile(edited);
    if (!fresh.scene) {  // the nudge made the document unrenderable (e.g. a brush with no image)
      EXPECT_FALSE(incremental.scene) << what;
      continue;
    }
    ASSERT_TRUE(incremental.scene) << what << ": "
                                   << (incremental.errors.empty() ? "" : incremental.errors[0]);
    StageSet expected;
    expected.add(nudge.stage);
    EXPECT_EQ(incremental.changes.names(), expected.names()) << what;
    expect_only_stage_work(nudge.stage, since(compiler.counters(), before), what);
    EXPECT_EQ(testing::differing_pixels(testing::render_one_pass(incremental.scene),
                                        testing::render_one_pass(fresh.scene)),
              0u)
        << what << ": the edited scene renders otherwise than one compiled from scratch";
    ++tested;
  }
  EXPECT_GT(tested, 10);
}

INSTANTIATE_TEST_SUITE_P(ExampleScenes, StageTable,
                         ::testing::Values("cornell_outlines.json", "materials.json", "toon.json",
                                           "lights.json", "strokes_150.json", "npr_mesh.json", "mesh.json",
                                           "graph_toon_rim.json", "graph_painterly.json",
                                           "graph_xtoon_depth.json", "graph_outline_gradient.json"),
                         [](const auto& scene) { return scene.param.substr(0, scene.param.find('.')); });

}  // namespace
}  // namespace inkray
