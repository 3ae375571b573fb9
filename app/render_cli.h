// Command-line options of inkray-render and their parsing.
#pragma once

#include "core/film/film.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace inkray {

struct AovOutput {
  std::string name;
  std::filesystem::path file;  // empty with --samples: the AOV's sums go into the partial
};

// --frames: first-last every step, or the scene's frame_start..frame_end ("all").
struct FrameRange {
  bool all = false;
  int first = 1, last = 1, step = 1;
};

struct RenderCliOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  std::filesystem::path write_scene;  // --write-scene: save the scene as the editor would, then exit
  std::optional<int> spp, threads, width, height, seed;
  std::optional<double> time_seconds;
  std::optional<std::uint64_t> memory_limit;  // bytes; default: half the machine's memory
  std::vector<AovOutput> aovs;
  // --samples A B: passes [A, B) written as a partial (docs/final-renders.md).
  std::optional<std::pair<uint32_t, uint32_t>> samples;
  std::optional<PixelWindow> crop;           // --crop X0 Y0 X1 Y1
  std::optional<double> checkpoint_minutes;  // --checkpoint
  // --decide-lines FILE: write adaptive line sampling's decisions and render nothing;
  // --line-decisions FILE: a slice reads them (docs/final-renders.md, "Line decisions").
  std::filesystem::path decide_lines, line_decisions;
  bool resume = false;
  bool denoise = false;  // --denoise: -o is denoised, the raw image goes beside it (raw_image_path)
  // --noise-threshold: tiles whose estimated relative error is below it stop taking samples
  // once they have --min-spp (docs/architecture.md, "Adaptive sampling").
  std::optional<double> noise_threshold;
  std::optional<int> min_spp;
  std::optional<FrameRange> frames;
  // --lines-svg / --lines-pdf: the lines as vector files (docs/lines.md), written with
  // the image; --lines-svg-image puts the image under the lines in the SVG.
  std::filesystem::path lines_svg, lines_pdf;
  bool lines_svg_image = false;
  bool quiet = false;
  bool help = false;
  bool node_reference = false;  // print the material-graph node reference (Markdown) and exit
};

// Returns nullopt and sets *error to one line on bad arguments, including output paths
// that cannot be written or name the same file twice (checked before any rendering).
std::optional<RenderCliOptions> parse_render_cli(int argc, const char* const* argv, std::string* error);
extern const char* const kRenderCliHelp;

// "A-B[:STEP]", "A" or "all"; nullopt when it is none of them.
std::optional<FrameRange> parse_frame_range(std::string_view text);
// Every run of '#' in `path` replaced by `frame`, zero-padded to the run's length.
std::filesystem::path expand_frame_pattern(const std::filesystem::path& path, int frame);
bool has_frame_pattern(const std::filesystem::path& path);
// The frames a resolved range (not `all`) renders, first to last every step.
std::vector<int> frames_of(const FrameRange& range);
// "" when no two of `frames` write the same file and no frame writes one file twice, for
// -o and every file derived from it and every --aov; else one line naming the two frames,
// the file and the options whose patterns name it.
std::string check_frame_names(const RenderCliOptions& options, const std::vector<int>& frames);
// Where --checkpoint keeps the film of a render writing `output`.
std::filesystem::path checkpoint_path(const std::filesystem::path& output);

}  // namespace inkray
