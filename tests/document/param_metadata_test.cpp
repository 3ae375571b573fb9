// Every parameter list reads like an artist's tool: each parameter of every
// description struct (nodes included) has a label, a soft range inside its hard one,
// plain-text docs, a file type when it is a path and a valid kind when it refers to
// other items; and the panel's edits beyond one value (a locked scale, a new mix,
// refusing an edit that breaks the scene) do what they say.
#include "core/document/edit_checks.h"
#include "core/document/param_text.h"

#include "core/document/tagged_variant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace inkray {
namespace {

struct Found {
  std::string at;
  Param param;
};

// Every parameter reachable from a struct: groups, lists of structs, colour inputs'
// textures and a graph's nodes, each alternative of a variant.
struct Walk {
  std::string at;
  std::vector<Found>* out;

  template <class F>
  void operator()(const Param& p, F&) {
    const std::string here = at + "." + std::string(p.name);
    out->push_back({here, p});
    if constexpr (std::is_same_v<F, ColorInput>) {
      all<ColorInput>(here, out);
    } else if constexpr (std::is_same_v<F, std::vector<GraphNodeDesc>>) {
      all<NodeVariant>(here, out);
    } else if constexpr (requires(F & f) { f.front(); } && !std::is_same_v<F, std::string>) {
      if constexpr (ParamGroup<typename F::value_type>) one<typename F::value_type>(here, out);
    } else if constexpr (ParamGroup<F>) {
      one<F>(here, out);
    }
  }

  template <class T>
  static void one(const std::string& at, std::vector<Found>* out) {
    T value{};
    Walk walk{at, out};
    visit_params(value, walk);
  }
  template <class Variant>
  static void all(const std::string& at, std::vector<Found>* out) {
    for_each_alternative<Variant>([&]<class T>(std::type_identity<T>) {
      if constexpr (ParamGroup<T>) {
        if constexpr (Tagged<T>) {
          one<T>(at + "." + std::string(T::type_name), out);
        } else {
          one<T>(at, out);
        }
      }
    });
  }
};

std::vector<Found> every_param() {
  std::vector<Found> found;
  Walk::one<CameraDesc>("camera", &found);
  Walk::one<RenderSettings>("render", &found);
  Walk::one<OutlineDesc>("outlines", &found);
  Walk::one<StrokeEmitterDesc>("strokes", &found);
  Walk::one<ObjectDesc>("objects", &found);
  Walk::one<RotationDesc>("objects.transform.rotate", &found);
  Walk::one<LineOverrideDesc>("materials.lines", &found);
  Walk::all<ShapeVariant>("objects.shape", &found);
  Walk::all<MaterialVariant>("materials", &found);
  Walk::all<LightVariant>("lights", &found);
  Walk::all<EnvironmentDesc>("environment", &found);
  Walk::all<NodeVariant>("nodes", &found);
  return found;
}

TEST(ParamMetadata, WalkReachesEveryList) {
  const std::vector<Found> all = every_param();
  EXPECT_GT(all.size(), 200u);
  const auto has = [&](const std::string& at) {
    return std::any_of(all.begin(), all.end(), [&](const Found& f) { return f.at == at; });
  };
  EXPECT_TRUE(has("render.time_limit"));
  EXPECT_TRUE(has("outlines.silhouette.width"));
  EXPECT_TRUE(has("materials.toon.ramp_near"));
  EXPECT_TRUE(has("materials.mix.factor.image.path"));
  EXPECT_TRUE(has("materials.graph.nodes.color_ramp.stops.position"));
  EXPECT_TRUE(has("nodes.noise_texture.scale"));
}

TEST(ParamMetadata, EveryParamHasAReadableLabel) {
  for (const Found& f : every_param()) {
    const std::string label = param_label(f.param);
    EXPECT_FALSE(label.empty()) << f.at;
    EXPECT_EQ(label.find('_'), std::string::npos) << f.at << ": " << label;
    EXPECT_NE(label.front(), ' ') << f.at;
    EXPECT_NE(label.back(), ' ') << f.at;
    // Capitalised, but for a word that carries its own capitals ("sRGB").
    EXPECT_TRUE(std::isupper(static_cast<unsigned char>(label.front())) || label.rfind("sRGB", 0) == 0)
        << f.at << ": " << label;
  }
}

TEST(ParamMetadata, SoftRangesLieInsideHardRanges) {
  for (const Found& f : every_param()) {
    const Param& p = f.param;
    const bool soft_low = std::isfinite(p.soft_min), soft_high = std::isfinite(p.soft_max);
    EXPECT_EQ(soft_low, soft_high) << f.at << ": a soft range has both ends or none";
    if (soft_low) {
      EXPECT_TRUE(p.kind == ParamKind::number || p.kind == ParamKind::integer) << f.at;
      EXPECT_LT(p.soft_min, p.soft_max) << f.at;
      EXPECT_GE(p.soft_min, p.min) << f.at;
      EXPECT_LE(p.soft_max, p.max) << f.at;
    }
    if (p.logarithmic) {
      ASSERT_TRUE(soft_low) << f.at << ": a logarithmic slider needs its soft range";
      EXPECT_GT(p.soft_min, 0.0) << f.at << ": a logarithmic slider starts above 0";
      // ImGui reads values below the last shown decimal as 0 on a log slider.
      const auto range = slider_range(p);
      ASSERT_TRUE(range) << f.at;
      EXPECT_LE(std::pow(10.0, -slider_decimals(*range)), p.soft_min) << f.at;
    }
    // A linear slider over a wide range turns a small drag into a jump.
    if (const auto range = slider_range(p); range && !range->logarithmic) {
      EXPECT_LE(range->max - range->min, p.kind == ParamKind::integer ? 64.0 : 360.0) << f.at;
    }
  }
}

TEST(ParamMetadata, TooltipsArePlainText) {
  for (const Found& f : every_param()) {
    const std::string tip = param_tooltip(f.param, true);
    EXPECT_EQ(tip.find('`'), std::string::npos) << f.at << ": " << tip;
    EXPECT_NE(tip.find("JSON key: " + std::string(f.param.name)), std::string::npos) << f.at;
    const std::string end = "Ctrl+click to type a value.";
    EXPECT_EQ(tip.substr(tip.size() - end.size()), end) << f.at;
  }
}

TEST(ParamMetadata, ReferencesAndPathsAreDeclared) {
  for (const Found& f : every_param()) {
    const Param& p = f.param;
    if (p.refers_to != Ref::none) {
      EXPECT_EQ(p.kind, ParamKind::text) << f.at;
      EXPECT_LE(int(p.refers_to), int(Ref::light)) << f.at;
    }
    EXPECT_EQ(p.kind == ParamKind::path, p.file_type != FileType::none) << f.at;
    if (p.kind == ParamKind::path) {
      EXPECT_FALSE(file_extensions(p.file_type).empty()) << f.at;
    }
  }
  const auto refers = [](const std::string& at) {
    for (const Found& f : every_param())
      if (f.at == at) return f.param.refers_to;
    return Ref::none;
  };
  EXPECT_EQ(refers("objects.material"), Ref::material);
  EXPECT_EQ(refers("materials.mix.a"), Ref::material);
  EXPECT_EQ(refers("materials.mix.b"), Ref::material);
  EXPECT_EQ(refers("strokes.object"), Ref::object);
}

TEST(ParamText, DerivedLabels) {
  EXPECT_EQ(derived_label("time_limit"), "Time limit");
  EXPECT_EQ(derived_label("ramp_near"), "Ramp near");
  EXPECT_EQ(derived_label("max_depth"), "Max depth");
  EXPECT_EQ(derived_label("spp"), "Samples per pixel");
  EXPECT_EQ(derived_label("ior"), "IOR");
  EXPECT_EQ(derived_label("srgb"), "sRGB");
  EXPECT_EQ(derived_label("color1"), "Colour 1");
  EXPECT_EQ(derived_label("edge_u"), "Edge U");
  EXPECT_EQ(derived_label("rgb_to_hsv"), "RGB to HSV");
  EXPECT_EQ(derived_label("object_id"), "Object ID");
  EXPECT_EQ(derived_label("fac"), "Factor");
}

TEST(ParamText, PlainTextKeepsProducts) {
  EXPECT_EQ(plain_text("Line width in `unit`"), "Line width in unit");
  EXPECT_EQ(plain_text("radiance = color * strength"), "radiance = color * strength");
  EXPECT_EQ(plain_text("**bold** and *emphasis*"), "bold and emphasis");
  const std::string tip = param_tooltip(number("time_limit", 0, 1e7, "Stop after `n` seconds"), true);
  EXPECT_EQ(tip, "Stop after n seconds\n\nJSON key: time_limit\nCtrl+click to type a value.");
  EXPECT_EQ(param_tooltip(toggle("rim", "Add a rim light"), false), "Add a rim light\n\nJSON key: rim");
}

// The outline width used to slide linearly over 0..1000: 40 px of a 250 px slider moved
// a 5 px line to 186 px. On its logarithmic soft range the same drag stays moderate.
TEST(ParamText, OutlineWidthSlidesLogarithmically) {
  Param width;
  for (const Found& f : every_param())
    if (f.at == "outlines.width") width = f.param;
  const auto range = slider_range(width);
  ASSERT_TRUE(range);
  EXPECT_TRUE(range->logarithmic);
  EXPECT_LE(range->max, 20.0);
  EXPECT_EQ(width.max, 1000.0);  // typed values keep the hard range
  const double t = std::log(5.0 / range->min) / std::log(range->max / range->min) + 40.0 / 250.0;
  const double dragged = range->min * std::pow(range->max / range->min, t);
  EXPECT_LT(dragged, 15.0);
  EXPECT_GT(dragged, 5.0);
}

TEST(ParamText, ChosenPathsAreRelativeInsideTheSceneFolder) {
  EXPECT_EQ(path_in_scene("/work/scenes/textures/wood.png", "/work/scenes"), "textures/wood.png");
  EXPECT_EQ(path_in_scene("/work/scenes/../meshes/bunny.obj", "/work/scenes"), "/work/meshes/bunny.obj");
  EXPECT_EQ(path_in_scene("/elsewhere/a.png", "/work/scenes"), "/elsewhere/a.png");
}

TEST(ParamText, LockedScaleScalesAllThreeAlike) {
  EXPECT_EQ(locked_scale(Vec3(1.f, 2.f, 3.f), Vec3(2.f, 2.f, 3.f)), Vec3(2.f, 4.f, 6.f));
  EXPECT_EQ(locked_scale(Vec3(1.f, 2.f, 3.f), Vec3(1.f, 1.f, 3.f)), Vec3(0.5f, 1.f, 1.5f));
  EXPECT_EQ(locked_scale(Vec3(2.f), Vec3(2.f, 2.f, -1.f)), Vec3(-1.f));
  // No proportion from or to zero: the scale stays.
  EXPECT_EQ(locked_scale(Vec3(0.f, 1.f, 1.f), Vec3(1.f, 1.f, 1.f)), Vec3(0.f, 1.f, 1.f));
  EXPECT_EQ(locked_scale(Vec3(1.f), Vec3(0.f, 1.f, 1.f)), Vec3(1.f));
  EXPECT_EQ(locked_scale(Vec3(1.f, 2.f, 3.f), Vec3(1.f, 2.f, 3.f)), Vec3(1.f, 2.f, 3.f));
}

SceneDesc scene_with_materials(std::vector<MaterialDesc> materials) {
  SceneDesc scene;
  scene.materials = std::move(materials);
  ObjectDesc ball;
  ball.name = "ball";
  ball.material = scene.materials.back().name;
  scene.objects.push_back(ball);
  return scene;
}

// What the editor did before: the type combo made a mix with no inputs, which the
// renderer then refused ("no material named \"\"").
TEST(ParamText, SwitchingToMixWithoutInputsIsAProblem) {
  const SceneDesc before = scene_with_materials({{"red", DiffuseDesc{}, {}}, {"blend", DiffuseDesc{}, {}}});
  SceneDesc after = before;
  after.materials[1].data = MixDesc{};
  const std::vector<std::string> added = problems_added(before, after);
  ASSERT_EQ(added.size(), 2u);
  EXPECT_NE(added[0].find("materials[1].a"), std::string::npos) << added[0];
  EXPECT_NE(added[1].find("materials[1].b"), std::string::npos) << added[1];
}

TEST(ParamText, SwitchingToMixPicksTwoOtherMaterials) {
  const SceneDesc before = scene_with_materials(
      {{"red", DiffuseDesc{}, {}}, {"gold", ConductorDesc{}, {}}, {"blend", DiffuseDesc{}, {}}});
  SceneDesc after = before;
  after.materials[2].data = MixDesc{};
  give_mix_inputs(after, 2);
  const MixDesc& mix = std::get<MixDesc>(after.materials[2].data);
  EXPECT_EQ(mix.a, "red");
  EXPECT_EQ(mix.b, "gold");
  EXPECT_EQ(after.materials.size(), 3u);
  EXPECT_TRUE(problems_added(before, after).empty());
}

TEST(ParamText, SwitchingToMixCreatesInputsWhenThereAreNone) {
  // The only other material is a mix (a cycle waiting to happen) or there is none at all.
  for (const bool with_other_mix : {false, true}) {
    std::vector<MaterialDesc> materials = {{"blend", DiffuseDesc{}, {}}};
    if (with_other_mix)
      materials.insert(materials.begin(), {"other", MixDesc{"blend", "blend", Color(0.5f)}, {}});
    const SceneDesc before = scene_with_materials(materials);
    SceneDesc after = before;
    const size_t index = after.materials.size() - 1;
    after.materials[index].data = MixDesc{};
    give_mix_inputs(after, index);
    const MixDesc& mix = std::get<MixDesc>(after.materials[index].data);
    EXPECT_NE(mix.a, mix.b);
    EXPECT_EQ(after.materials.size(), before.materials.size() + 2);
    const std::vector<std::string> added = problems_added(before, after);
    EXPECT_TRUE(added.empty()) << added.front();
  }
}

TEST(ParamText, SwitchingToMixKeepsGoodInputs) {
  SceneDesc scene = scene_with_materials({{"red", DiffuseDesc{}, {}},
                                          {"gold", ConductorDesc{}, {}},
                                          {"blend", MixDesc{"gold", "", Color(0.5f)}, {}}});
  give_mix_inputs(scene, 2);
  const MixDesc& mix = std::get<MixDesc>(scene.materials[2].data);
  EXPECT_EQ(mix.a, "gold");
  EXPECT_EQ(mix.b, "red");
}

TEST(ParamText, EditsThatBreakTheSceneAreNamed) {
  SceneDesc before = scene_with_materials({{"red", DiffuseDesc{}, {}}});
  StrokeEmitterDesc strokes;
  strokes.name = "strokes";
  strokes.object = "ball";
  before.strokes.push_back(strokes);

  SceneDesc wider = before;
  wider.strokes[0].width_max = 0.5f;
  EXPECT_TRUE(problems_added(before, wider).empty());

  SceneDesc inverted = before;
  inverted.strokes[0].width_min = 0.9f;
  const std::vector<std::string> added = problems_added(before, inverted);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_NE(added[0].find("strokes[0].width_min"), std::string::npos) << added[0];

  SceneDesc huge = before;
  huge.render.width = huge.render.height = 16384;
  EXPECT_EQ(problems_added(before, huge).size(), 1u);

  // A problem the scene had already is not the edit's.
  EXPECT_TRUE(problems_added(inverted, inverted).empty());
}

}  // namespace
}  // namespace inkray
