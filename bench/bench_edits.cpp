// inkray-bench-edits SCENE.json [EDITS [KIND]]: what one editor edit costs on the way to the
// renderer, step by step, without a window: the panel's copy of the document and its
// change, the check that the edit adds no problem (problems_added), the undoable edit
// (Document::edit), the renderer's copy (ProgressiveRenderer::submit) and the
// incremental compile the viewport runs, and the viewport's first preview of the result
// (one pass at 1/8 resolution, set_scene included). Prints the median and p95 of each step for
// material, transform, camera and (with stroke emitters) brush edits, or of KIND's alone
// (docs/benchmarks.md, "Large documents").
#include "core/compiler/compile.h"
#include "core/document/edit_checks.h"
#include "core/document/json_io.h"
#include "core/render/render_session.h"
#include "ui/model/document.h"
#include "ui/viewport/camera_controller.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {
namespace {

using Clock = std::chrono::steady_clock;

// The viewport's usual first preview (ProgressiveRenderer adapts it between 1/8 and 1/32).
constexpr int kPreviewDivisor = 8;

double ms(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

enum class Kind { material, transform, camera, brush };
constexpr std::array<const char*, 4> kKindNames{"material", "transform", "camera", "brush"};

int first_used_material(const SceneDesc& s) {
  for (size_t m = 0; m < s.materials.size(); ++m)
    for (size_t o = 0; o < std::min<size_t>(s.objects.size(), 64); ++o)
      if (s.objects[o].material == s.materials[m].name) return int(m);
  return 0;
}

// The change a panel makes: one parameter, from the value it had when the kind started.
void change(Kind kind, int step, const SceneDesc& base, SceneDesc& s) {
  const float t = float(step % 2 ? step : -step);
  switch (kind) {
    case Kind::material: {
      const size_t m = size_t(first_used_material(base));
      if (auto* toon = std::get_if<ToonDesc>(&s.materials[m].data))
        toon->shadow_color = Color(0.1f + 0.001f * float(step));
      else if (auto* diffuse = std::get_if<DiffuseDesc>(&s.materials[m].data))
        diffuse->albedo = Color(0.5f + 0.001f * float(step));
      break;
    }
    case Kind::transform:
      s.objects[0].transform.translate = base.objects[0].transform.translate + Vec3(0.01f * t, 0.f, 0.f);
      break;
    case Kind::camera:
      s.camera = orbit(s.camera, 0.02f, 0.f);
      break;
    case Kind::brush:
      // The first emitter's brush, another each edit: procedural kinds in turn, each
      // at its own pressure.
      s.strokes[0].brush = step % 2 ? BrushKind::bristle : BrushKind::flat;
      s.strokes[0].pressure = 0.5f + 0.001f * float(step % 400);
      break;
  }
}

struct Steps {
  std::vector<double> copy, checks, edit, submit, compile, preview, total;
};

void print(const char* what, const std::vector<double>& v) {
  std::printf("  %-9s p50 %8.2f ms  p95 %8.2f ms\n", what, quantile(v, 0.5), quantile(v, 0.95));
}

// `only`: the one kind to time, or all of them when it names none.
int run(const char* file, int edits, std::string_view only) {
  const SceneLoadResult loaded = load_scene(file, ReadFor::editing);
  if (!loaded) {
    for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 1;
  }
  std::printf("%s: %zu objects, %zu materials, %zu stroke emitters; %d edits of each kind\n", file,
              loaded.scene->objects.size(), loaded.scene->materials.size(), loaded.scene->strokes.size(),
              edits);
  for (size_t k = 0; k < kKindNames.size(); ++k) {
    const Kind kind = Kind(k);
    if ((kind == Kind::brush && loaded.scene->strokes.empty()) || (!only.empty() && only != kKindNames[k]))
      continue;
    Document document;
    document.reset(*loaded.scene, file);
    SceneCompiler compiler;
    CompileOptions options;
    options.stand_in_for_broken_graphs = true;
    options.stand_in_for_missing_assets = true;
    if (!compiler.compile(document.scene(), options).scene) {
      std::fprintf(stderr, "%s does not compile\n", file);
      return 1;
    }
    const SceneDesc base = document.scene();
    RenderSession session;
    Steps steps;
    for (int i = 0; i < edits; ++i) {
      const Clock::time_point t0 = Clock::now();
      SceneDesc after = document.scene();
      change(kind, i + 1, base, after);
      const Clock::time_point t1 = Clock::now();
      const bool refused = !problems_added(document.scene(), after).empty();
      const Clock::time_point t2 = Clock::now();
      document.edit(std::move(after), "Edit", "bench");
      const Clock::time_point t3 = Clock::now();
      const SceneDesc pending = document.scene();
      const Clock::time_point t4 = Clock::now();
      const CompileResult compiled = compiler.compile(pending, options);
      const Clock::time_point t5 = Clock::now();
      if (refused || !compiled.scene) {
        std::fprintf(stderr, "edit %d of %s was refused\n", i, kKindNames[k]);
        return 1;
      }
      session.set_scene(compiled.scene, {}, kPreviewDivisor);
      session.render_pass();
      const Clock::time_point t6 = Clock::now();
      steps.copy.push_back(ms(t0, t1));
      steps.checks.push_back(ms(t1, t2));
      steps.edit.push_back(ms(t2, t3));
      steps.submit.push_back(ms(t3, t4));
      steps.compile.push_back(ms(t4, t5));
      steps.preview.push_back(ms(t5, t6));
      steps.total.push_back(ms(t0, t6));
    }
    std::printf("%s edit:\n", kKindNames[k]);
    print("copy", steps.copy);
    print("checks", steps.checks);
    print("edit", steps.edit);
    print("submit", steps.submit);
    print("compile", steps.compile);
    print("preview", steps.preview);
    print("total", steps.total);
  }
  return 0;
}

}  // namespace
}  // namespace inkray

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: inkray-bench-edits SCENE.json [EDITS [material|transform|camera|brush]]\n");
    return 2;
  }
  const int edits = argc >= 3 ? std::atoi(argv[2]) : 20;
  const std::string_view only = argc == 4 ? argv[3] : "";
  if (!only.empty() &&
      std::find(inkray::kKindNames.begin(), inkray::kKindNames.end(), only) == inkray::kKindNames.end()) {
    std::fprintf(stderr, "inkray-bench-edits: KIND must be material, transform, camera or brush\n");
    return 2;
  }
  if (edits < 1 || edits > 100000) {
    std::fprintf(stderr, "inkray-bench-edits: EDITS must be 1 to 100000\n");
    return 2;
  }
  return inkray::run(argv[1], edits, only);
}
