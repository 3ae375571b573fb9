// Command-line options of inkray-render and their parsing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace inkray {

struct AovOutput {
  std::string name;
  std::filesystem::path file;
};

struct RenderCliOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  std::filesystem::path write_scene;  // --write-scene: save the scene as the editor would, then exit
  std::optional<int> spp, threads, width, height, seed;
  std::optional<double> time_seconds;
  std::optional<std::uint64_t> memory_limit;  // bytes; default: half the machine's memory
  std::vector<AovOutput> aovs;
  bool quiet = false;
  bool help = false;
  bool node_reference = false;  // print the material-graph node reference (Markdown) and exit
};

// Returns nullopt and sets *error to one line on bad arguments, including output paths
// that cannot be written or name the same file twice (checked before any rendering).
std::optional<RenderCliOptions> parse_render_cli(int argc, const char* const* argv, std::string* error);
extern const char* const kRenderCliHelp;

}  // namespace inkray
