// inkray-merge: adds partial renders (inkray-render --samples, --crop) up to the
// image one machine would have rendered, or to a partial again.
#include "core/compiler/compile_view.h"
#include "core/document/animation.h"
#include "core/document/json_io.h"
#include "core/film/denoise.h"
#include "core/film/film_partial.h"
#include "core/film/partial_merge.h"
#include "core/image/image_io.h"
#include "core/io/output_set.h"
#include "core/render/render_outputs.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace inkray;
namespace fs = std::filesystem;

const char* const kHelp = R"(inkray-merge: add partial renders up to the final image.

usage: inkray-merge OUT.(png|pfm|exr) PARTIAL.exr... [--aov NAME=FILE]... [options]
       inkray-merge OUT.partial.exr PARTIAL.exr... [options]

The partials are inkray-render --samples files of one render: the same scene, settings, frame
and image size, any mix of sample ranges and crop windows. Together they must hold every pixel,
each pixel's samples once and from sample 0 on without a gap; the image is then resolved
exactly as inkray-render resolves it (lines, painterly filter, format by extension), equal to
the render of all those samples on one machine (docs/final-renders.md).
An OUT ending in .partial.exr is a partial again, for merging in stages: then the partials
must hold one window with one range of samples for all its pixels.

  --aov NAME=FILE       also write an AOV (see inkray-render --help); its sums must be in the
                        partials (inkray-render --aov NAME); may be repeated
  --denoise             write OUT denoised and the image as merged beside it as OUT_raw.EXT; the
                        partials must keep the denoiser's features (inkray-render --samples with
                        --denoise)
  --lines-svg FILE      also write the lines as an SVG file, as inkray-render --lines-svg does
  --lines-svg-image     put the image under the lines in the SVG
  --lines-pdf FILE      also write the lines as a one-page PDF file
  --threads N           worker threads for the painterly filter (default: one per hardware thread)
  -q, --quiet           print nothing on success
  -h, --help            this text

Exit status: 0 on success, 1 on a partial or output error, 2 on bad arguments.
)";

struct MergeOptions {
  fs::path output;
  std::vector<fs::path> partials;
  std::vector<AovFile> aovs;
  LineFiles lines;
  int threads = 0;
  bool denoise = false;
  bool quiet = false;
  bool help = false;
};

bool ends_with(const std::string& s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

bool writes_partial(const fs::path& output) { return ends_with(output.string(), ".partial.exr"); }

std::optional<MergeOptions> parse(int argc, char** argv, std::string* error) {
  MergeOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const auto value = [&]() -> std::optional<std::string_view> {
      if (i + 1 >= argc) {
        *error = std::string(arg) + ": missing value";
        return std::nullopt;
      }
      return std::string_view(argv[++i]);
    };
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      return o;
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else if (arg == "--denoise") {
      o.denoise = true;
    } else if (arg == "--lines-svg-image") {
      o.lines.svg_image = true;
    } else if (arg == "--lines-svg" || arg == "--lines-pdf") {
      const auto v = value();
      if (!v) return std::nullopt;
      const std::string_view extension = arg == "--lines-svg" ? ".svg" : ".pdf";
      if (!ends_with(std::string(*v), extension)) {
        *error = std::string(arg) + ": " + std::string(*v) + ": expected a file ending in " +
                 std::string(extension);
        return std::nullopt;
      }
      (arg == "--lines-svg" ? o.lines.svg : o.lines.pdf) = std::string(*v);
    } else if (arg == "--threads") {
      const auto v = value();
      if (!v) return std::nullopt;
      auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), o.threads);
      if (ec != std::errc() || ptr != v->data() + v->size() || o.threads < 1 || o.threads > 1024) {
        *error = "--threads: expected an integer in [1, 1024], got \"" + std::string(*v) + "\"";
        return std::nullopt;
      }
    } else if (arg == "--aov") {
      const auto v = value();
      if (!v) return std::nullopt;
      const size_t eq = v->find('=');
      const auto aov = aov_from_name(v->substr(0, eq));
      if (eq == std::string_view::npos || eq + 1 == v->size() || !aov) {
        *error = "--aov: expected NAME=FILE with NAME one of " + aov_name_list() + "; got \"" +
                 std::string(*v) + "\"";
        return std::nullopt;
      }
      o.aovs.push_back({*aov, std::string(v->substr(eq + 1))});
    } else if (!arg.empty() && arg[0] == '-') {
      *error = "unknown option \"" + std::string(arg) + "\" (see --help)";
      return std::nullopt;
    } else if (o.output.empty()) {
      o.output = std::string(arg);
    } else {
      o.partials.push_back(std::string(arg));
    }
  }
  if (o.output.empty() || o.partials.empty()) {
    *error =
        "expected an output and at least one partial (usage: inkray-merge OUT.png PARTIAL.exr...; see "
        "--help)";
    return std::nullopt;
  }
  if (o.lines.svg_image && o.lines.svg.empty()) {
    *error = "--lines-svg-image puts the image under the lines of --lines-svg FILE: add it";
    return std::nullopt;
  }
  if (writes_partial(o.output) && (!o.aovs.empty() || o.denoise || o.lines.any())) {
    *error = std::string(o.denoise         ? "--denoise"
                         : !o.aovs.empty() ? "--aov"
                                           : "--lines-svg/--lines-pdf") +
             ": a partial output keeps the partials' sums; give it when merging to an image";
    return std::nullopt;
  }
  std::vector<PlannedOutput> outputs = {{o.output.string(), o.output}};
  if (o.denoise)
    outputs.push_back(
        {"--denoise's raw image " + raw_image_path(o.output).string(), raw_image_path(o.output)});
  for (const AovFile& a : o.aovs)
    outputs.push_back({"--aov " + std::string(kAovNames[size_t(a.aov)]) + "=" + a.file.string(), a.file});
  for (const auto& planned : outputs)
    if (image_format_of(planned.file) == ImageFormat::unknown) {
      *error = planned.file.string() + ": unknown image format (expected .png, .pfm or .exr)";
      return std::nullopt;
    }
  if (!o.lines.svg.empty()) outputs.push_back({"--lines-svg " + o.lines.svg.string(), o.lines.svg});
  if (!o.lines.pdf.empty()) outputs.push_back({"--lines-pdf " + o.lines.pdf.string(), o.lines.pdf});
  for (const fs::path& p : o.partials) {
    std::error_code ec;
    if (fs::equivalent(p, o.output, ec)) {
      *error = o.output.string() + ": the output is also a partial to merge";
      return std::nullopt;
    }
  }
  if (std::string problem = check_outputs(outputs); !problem.empty()) {
    *error = std::move(problem);
    return std::nullopt;
  }
  return o;
}

int run(const MergeOptions& opt) {
  const bool partial = writes_partial(opt.output);
  MergedFilm merged;
  std::string error;
  if (!merge_partials(opt.partials, !partial, &merged, &error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  const PartialInfo& info = merged.info;
  std::optional<Denoised> denoised;
  if (partial) {
    if (!write_partial_file(*merged.film, info, opt.output, &error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 1;
    }
  } else {
    for (const AovFile& a : opt.aovs)
      if (!is_outline_aov(a.aov) && !info.aovs.has(a.aov)) {
        std::fprintf(stderr, "error: %s: the partials hold no %s sums (render them with --aov %s)\n",
                     opt.partials.front().c_str(), std::string(kAovNames[size_t(a.aov)]).c_str(),
                     std::string(kAovNames[size_t(a.aov)]).c_str());
        return 1;
      }
    if (opt.denoise && (info.aovs.bits & denoise_aovs().bits) != denoise_aovs().bits) {
      std::fprintf(stderr,
                   "error: %s: the partials hold none of the denoiser's features (render them with --samples "
                   "and --denoise)\n",
                   opt.partials.front().c_str());
      return 1;
    }
    // The settings the render resolved with: the scene the partials carry, at their frame.
    SceneLoadResult scene = parse_scene(info.scene, opt.partials.front().parent_path(),
                                        opt.partials.front().string() + ": inkray.scene", ReadFor::editing);
    if (!scene) {
      // One line: the first problem (a partial's scene was written by inkray, so any is damage).
      const std::string first = scene.errors.empty() ? "unreadable" : scene.errors.front();
      std::fprintf(stderr, "error: %s%s\n", first.c_str(),
                   scene.errors.size() > 1
                       ? (" (and " + std::to_string(scene.errors.size() - 1) + " more)").c_str()
                       : "");
      return 1;
    }
    SceneDesc desc = std::move(*scene.scene);
    if (!desc.animation.empty()) desc = scene_at_frame(desc, desc.render.frame);
    ThreadBudget pool(opt.threads);
    if (opt.denoise) denoised = denoise(*merged.film, &pool);
    std::vector<std::string> problems;
    const ResolveSettings resolve =
        compile_resolve_settings(desc, read_line_brushes(desc.base_dir), &problems);
    if (!problems.empty()) {
      std::fprintf(stderr, "error: %s\n", problems.front().c_str());
      return 1;
    }
    switch (write_film_outputs(*merged.film, resolve, opt.output, opt.aovs, &error, &pool, {}, {},
                               denoised ? &denoised->image : nullptr, opt.lines)) {
      case OutputsWritten::all:
        break;
      case OutputsWritten::cancelled:
      case OutputsWritten::failed:
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return 1;
    }
  }
  if (!opt.quiet) {
    std::printf("%s: %zu partials, %dx%d, frame %g, ", opt.output.c_str(), opt.partials.size(), info.width,
                info.height, double(info.frame));
    if (merged.min_samples == merged.max_samples)
      std::printf("%u spp", merged.min_samples);
    else
      std::printf("%u-%u spp", merged.min_samples, merged.max_samples);
    if (partial) std::printf(", partial: %s", describe_partial(info).c_str());
    if (info.nonfinite) std::printf(", %llu non-finite samples dropped", (unsigned long long)info.nonfinite);
    if (denoised) std::printf(", denoised: estimated rel. error %.5f", denoised->relative_error);
    std::printf("\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string error;
  const auto options = parse(argc, argv, &error);
  if (!options) {
    std::fprintf(stderr, "inkray-merge: %s\n", error.c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  try {
    return run(*options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inkray-merge: %s\n", e.what());
    return 1;
  }
}
