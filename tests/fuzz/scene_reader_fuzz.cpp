// Fuzz harness for the scene reader: parse_scene must never throw, and a scene it
// accepts, for rendering or for editing, must survive scene_to_string -> parse_scene
// -> scene_to_string unchanged (what the editor saves, it must open again).
#include "core/document/json_io.h"
#include "tests/fuzz/fuzz_targets.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace inkray {
namespace {

// The written text of the scene, or nullopt when the reader refused the input.
std::optional<std::string> check_round_trip(std::string_view text, ReadFor purpose) {
  // The seeds' relative mesh and texture paths resolve here; the reader only checks
  // that the files exist, so no asset is loaded.
  static const std::filesystem::path base_dir =
      std::filesystem::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid";
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

}  // namespace

int fuzz_scene_reader(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::optional<std::string> for_rendering = check_round_trip(text, ReadFor::rendering);
  const std::optional<std::string> for_editing = check_round_trip(text, ReadFor::editing);
  // Editing only tolerates more; it must never read a renderable scene differently.
  if (for_rendering && for_editing != for_rendering)
    fuzz_fail("the scene reads differently for editing than for rendering");
  return 0;
}

}  // namespace inkray
