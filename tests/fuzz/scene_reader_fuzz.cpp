// Fuzz harness for the scene reader: parse_scene must never throw, and a scene it
// accepts, for rendering or for editing, must survive scene_to_string -> parse_scene
// -> scene_to_string unchanged (what the editor saves, it must open again). Its
// material graphs must compile or be refused with messages, never crash, and a
// compiled graph must give finite values at any hit.
#include "core/compiler/compile_graph.h"
#include "core/document/json_io.h"
#include "core/materials/shader_eval.h"
#include "tests/fuzz/fuzz_targets.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace inkray {
namespace {

// The seeds' relative mesh and texture paths resolve here; the reader only checks
// that the files exist, so no asset is loaded (graphs load their images: the harness
// sees the same files).
const std::filesystem::path& seeds_dir() {
  static const std::filesystem::path dir =
      std::filesystem::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid";
  return dir;
}

// The written text of the scene, or nullopt when the reader refused the input.
std::optional<std::string> check_round_trip(std::string_view text, ReadFor purpose) {
  const std::filesystem::path& base_dir = seeds_dir();
  const std::string mode = purpose == ReadFor::editing ? "for editing" : "for rendering";

  const SceneLoadResult first = parse_scene(text, base_dir, "fuzz.json", purpose);
  if (!first) return std::nullopt;
  const std::string written = scene_to_string(*first.scene);

  const SceneLoadResult second = parse_scene(written, base_dir, "rewritten.json", purpose);
  if (!second) {
    std::string errors;
    for (const std::string& line : second.errors) errors += "\n  " + line;
    fuzz_fail("a scene read " + mode + " was written back as one the reader rejects:" + errors +
              "\n--- written ---\n" + written);
  }
  const std::string rewritten = scene_to_string(*second.scene);
  if (rewritten != written) {
    fuzz_fail("writing a scene read " + mode + ", reading it and writing it again changed the text:\n" +
              "--- first ---\n" + written + "--- second ---\n" + rewritten);
  }
  return written;
}

void check_graphs(const SceneDesc& scene) {
  AssetCache assets;
  for (const MaterialDesc& m : scene.materials) {
    const auto* graph = std::get_if<GraphDesc>(&m.data);
    if (!graph) continue;
    std::vector<std::string> errors;
    const auto program = compile_graph(*graph, scene.base_dir, assets, errors);
    if (!program) {
      if (errors.empty()) fuzz_fail("material \"" + m.name + "\": a graph was refused without a message");
      continue;
    }
    SurfaceInteraction si;
    si.p = Point3(0.3f, -2.f, 1e3f);
    si.uv = Vec2(0.7f, -0.2f);
    ShadingPoint sp = shading_point(si, glm::normalize(Vec3(0.2f, 0.3f, 1.f)));
    sp.depth = 5.f;
    ShaderRegisters registers;
    run_shader(*program, sp, registers);
    for (int r = 0; r < program->register_count; ++r)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(registers[size_t(r)][c]))
          fuzz_fail("material \"" + m.name + "\": a graph computed a non-finite value");
    Material scratch;
    for (float u : {0.f, 0.37f, 0.99f}) pick_closure(*program, registers, u, scratch);
  }
}

}  // namespace

int fuzz_scene_reader(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::optional<std::string> for_rendering = check_round_trip(text, ReadFor::rendering);
  if (for_rendering) {
    const SceneLoadResult read = parse_scene(*for_rendering, seeds_dir(), "fuzz.json");
    if (read) check_graphs(*read.scene);
  }
  const std::optional<std::string> for_editing = check_round_trip(text, ReadFor::editing);
  // Editing only tolerates more; it must never read a renderable scene differently.
  if (for_rendering && for_editing != for_rendering)
    fuzz_fail("the scene reads differently for editing than for rendering");
  return 0;
}

}  // namespace inkray
