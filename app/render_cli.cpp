#include "app/render_cli.h"

#include "app/cli_numbers.h"
#include "core/film/film.h"
#include "core/image/image_io.h"
#include "core/io/output_set.h"
#include "core/render/render_outputs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <tuple>

namespace inkray {

const char* const kRenderCliHelp = R"(inkray-render: render an inkray scene without a window.

usage: inkray-render SCENE.json -o OUT.(png|pfm|exr) [options]
       inkray-render SCENE.json --samples A B -o PART.exr [--line-decisions FILE] [options]
       inkray-render SCENE.json --decide-lines FILE [options]
       inkray-render SCENE.json --write-scene OUT.json


  -o, --output FILE     image to write; .png is 8-bit sRGB, .pfm and .exr are linear float
  --spp N               samples per pixel (default: the scene's render.spp)
  --time SECONDS        the whole run, reading and building the scene included, takes at most this
                        long (default: the scene's render.time_limit; 0 means no limit); the render
                        stops at whichever of --spp and --time comes first, and a scene that cannot
                        be built in time is an error that writes nothing; with --frames, each frame
  --memory-limit SIZE   refuse a scene whose estimated memory is above SIZE (bytes, or with a K, M,
                        G or T suffix; default: half of this machine's memory)
  --threads N           worker threads (default: one per hardware thread)
  --width W --height H  override the scene's resolution (the aspect ratio follows)
  --seed S              seed of every random decision (default: the scene's render.seed)
  --aov NAME=FILE       also write an AOV; may be repeated. NAME is a first-hit AOV (albedo, normal,
                        depth, object_id, material_id, toon_band) or an outline opacity: outline (all line
                        types) or outline_depth, outline_crease, outline_intersection,
                        outline_material, outline_object, outline_silhouette (one type each).
                        With --samples, --aov NAME keeps the AOV's sums in the partial
  --denoise             write -o denoised (lines, ids and toon bands stay crisp) and the image as
                        rendered beside it as OUT_raw.EXT; prints the denoised image's estimated
                        error. With --samples, the partial keeps the denoiser's features for
                        inkray-merge --denoise
  --noise-threshold E   adaptive sampling: a 16x16 tile whose estimated relative error (smoothed
                        over its neighbours) is below E stops taking samples; the others go on up
                        to --spp, within --time
  --min-spp N           samples every pixel takes before adaptive sampling may stop it (default 16)
  --write-scene FILE    read and check the scene, write it as the editor saves it (every
                        parameter, asset paths relative to FILE's folder) and exit without
                        rendering; upgrades and normalises scene files
  -q, --quiet           no progress bar
  --node-reference      print the reference of material-graph nodes (Markdown), generated from
                        their parameter lists, and exit
  -h, --help            this text

Final renders on many machines (docs/final-renders.md):
  --frames A-B[:STEP]   render frames A to B (both included) every STEP frames; "all" is the
                        scene's render.frame_start to frame_end, and a single number one frame.
                        A run of '#' in -o and in --aov files becomes the frame number, zero-padded
                        (out_####.png -> out_0001.png); more than one frame needs it, and a range
                        in which two frames would write the same file is refused
  --samples A B         render only samples A to B (B excluded) of every pixel, as they fall in a
                        render of all of them, and write -o (.exr) as a partial: the film's sums
                        with the scene and its settings. inkray-merge adds partials up to the image
  --crop X0 Y0 X1 Y1    render only pixels X0 to X1 and Y0 to Y1 (X1, Y1 excluded); the image and
                        AOVs written are that window (the painterly filter sees nothing around it),
                        and with --samples the partial holds it
  --checkpoint MINUTES  every MINUTES, and when the time limit ends the render early, write the
                        film as a partial to OUT.checkpoint.exr (OUT being -o); it is removed when
                        the render completes. A checkpoint that cannot be written makes the run
                        exit 1 (the render goes on and its image is still written)
  --resume              continue from OUT.checkpoint.exr when there is one (refused when it is of
                        another scene, setting, frame or size); with none, skip the render when
                        its image and AOV files all exist
  --decide-lines FILE   trace only what adaptive line sampling decides in a render's first passes
                        (the whole image, at --width, --height and --seed) and write it to FILE;
                        renders nothing. Made once for a render split into sample slices
  --line-decisions FILE with --samples A B: read those decisions instead of tracing them again
                        (slices that start before they were all made trace them as usual);
                        refused when FILE is of another scene, setting, frame or size

The same scene, seed and sample count give the same image at any thread count, on one machine
or merged from slices and crops of it.
After the render a table lists, per pass checkpoint, the samples per pixel, the elapsed
seconds and the estimated relative error (from the difference of the two half-buffers);
with --frames, one line per frame.
Exit status: 0 on success, 1 on a scene or output error, 2 on bad arguments.
)";

namespace {

using cli::parse_number;

// "8G", "512M", "64k", "1000000": bytes, at least 1 MiB and below 2^60.
std::optional<std::uint64_t> parse_size(std::string_view text) {
  int shift = 0;
  if (!text.empty()) {
    switch (text.back()) {
      case 'k':
      case 'K':
        shift = 10;
        break;
      case 'm':
      case 'M':
        shift = 20;
        break;
      case 'g':
      case 'G':
        shift = 30;
        break;
      case 't':
      case 'T':
        shift = 40;
        break;
      default:
        break;
    }
  }
  if (shift) text.remove_suffix(1);
  double value = 0.0;
  if (!parse_number(text, &value) || value <= 0.0) return std::nullopt;
  const double bytes = std::ldexp(value, shift);
  if (bytes < double(1 << 20) || bytes >= std::ldexp(1.0, 60)) return std::nullopt;
  return std::uint64_t(bytes);
}

// An integer with an optional sign at the start of `text`; advances past it.
bool take_int(std::string_view& text, int* out) {
  size_t n = 0;
  if (n < text.size() && (text[n] == '-' || text[n] == '+')) ++n;
  while (n < text.size() && text[n] >= '0' && text[n] <= '9') ++n;
  std::string_view digits = text.substr(0, n);
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  long v = 0;
  if (!parse_number(digits, &v) || v < -1000000 || v > 1000000) return false;
  *out = int(v);
  text.remove_prefix(n);
  return true;
}

}  // namespace

std::optional<FrameRange> parse_frame_range(std::string_view text) {
  FrameRange r;
  if (text == "all") {
    r.all = true;
    return r;
  }
  if (!take_int(text, &r.first)) return std::nullopt;
  r.last = r.first;
  if (!text.empty() && text[0] == '-') {
    text.remove_prefix(1);
    if (!take_int(text, &r.last)) return std::nullopt;
  }
  if (!text.empty() && text[0] == ':') {
    text.remove_prefix(1);
    if (!take_int(text, &r.step) || r.step < 1) return std::nullopt;
  }
  if (!text.empty() || r.last < r.first) return std::nullopt;
  return r;
}

bool has_frame_pattern(const std::filesystem::path& path) {
  return path.string().find('#') != std::string::npos;
}

std::filesystem::path expand_frame_pattern(const std::filesystem::path& path, int frame) {
  // As printf's "%0*d" with the run's length as width, but for a run of any length.
  const std::string in = path.string();
  const std::string digits = std::to_string(frame < 0 ? -static_cast<long long>(frame) : frame);
  const std::string sign = frame < 0 ? "-" : "";
  std::string out;
  for (size_t i = 0; i < in.size();) {
    if (in[i] != '#') {
      out += in[i++];
      continue;
    }
    size_t run = 0;
    while (i + run < in.size() && in[i + run] == '#') ++run;
    out += sign;
    if (run > sign.size() + digits.size()) out.append(run - sign.size() - digits.size(), '0');
    out += digits;
    i += run;
  }
  return out;
}

std::vector<int> frames_of(const FrameRange& range) {
  std::vector<int> frames;
  for (long long f = range.first; f <= range.last; f += range.step) frames.push_back(int(f));
  return frames;
}

std::string check_frame_names(const RenderCliOptions& o, const std::vector<int>& frames) {
  struct Pattern {
    std::string label;
    std::filesystem::path file;
  };
  std::vector<Pattern> patterns = {{"-o " + o.output.string(), o.output}};
  if (o.denoise && !o.samples) patterns.push_back({"--denoise's raw image", raw_image_path(o.output)});
  if (o.checkpoint_minutes || o.resume) patterns.push_back({"the checkpoint", checkpoint_path(o.output)});
  for (const auto& a : o.aovs)
    if (!a.file.empty()) patterns.push_back({"--aov " + a.name + "=" + a.file.string(), a.file});
  const auto name_of = [&](uint32_t pattern, uint32_t frame) {
    return expand_frame_pattern(patterns[pattern].file, frames[frame]).lexically_normal().string();
  };
  // Hashes sorted, so only names with equal hashes are compared: a range of a million
  // frames costs 16 bytes a name, not the names themselves.
  struct Name {
    size_t hash;
    uint32_t pattern, frame;
  };
  std::vector<Name> names;
  names.reserve(frames.size() * patterns.size());
  for (uint32_t f = 0; f < frames.size(); ++f)
    for (uint32_t p = 0; p < patterns.size(); ++p)
      names.push_back({std::hash<std::string>{}(name_of(p, f)), p, f});
  std::sort(names.begin(), names.end(), [](const Name& a, const Name& b) {
    return std::tie(a.hash, a.frame, a.pattern) < std::tie(b.hash, b.frame, b.pattern);
  });
  // Of all collisions, the one between the earliest frames is reported.
  const Name* first = nullptr;
  const Name* second = nullptr;
  for (size_t i = 0; i < names.size(); ++i)
    for (size_t j = i + 1; j < names.size() && names[j].hash == names[i].hash; ++j) {
      if (name_of(names[i].pattern, names[i].frame) != name_of(names[j].pattern, names[j].frame)) continue;
      if (!second || std::tie(names[j].frame, names[i].frame) < std::tie(second->frame, first->frame)) {
        first = &names[i];
        second = &names[j];
      }
    }
  if (!first) return "";
  const std::string file = name_of(first->pattern, first->frame);
  const std::string a = std::to_string(frames[first->frame]), b = std::to_string(frames[second->frame]);
  const std::string& la = patterns[first->pattern].label;
  const std::string& lb = patterns[second->pattern].label;
  if (first->frame == second->frame)
    return "frame " + a + " would write " + file + " twice (" + la + " and " + lb + ")";
  if (first->pattern == second->pattern)
    return "frames " + a + " and " + b + " would both write " + file + " (" + la + ")";
  return "frames " + a + " and " + b + " would both write " + file + " (" + la + " at frame " + a + ", " +
         lb + " at frame " + b + ")";
}

std::filesystem::path checkpoint_path(const std::filesystem::path& output) {
  return output.string() + ".checkpoint.exr";
}

std::optional<RenderCliOptions> parse_render_cli(int argc, const char* const* argv, std::string* error) {
  RenderCliOptions o;
  auto value_of = [&](int& i, std::string_view flag) -> std::optional<std::string_view> {
    if (i + 1 >= argc) {
      *error = std::string(flag) + ": missing value";
      return std::nullopt;
    }
    return std::string_view(argv[++i]);
  };
  auto int_option = [&](int& i, std::string_view flag, long lo, long hi, std::optional<int>* out) {
    const auto v = value_of(i, flag);
    if (!v) return false;
    long n = 0;
    if (!parse_number(*v, &n) || n < lo || n > hi) {
      *error = std::string(flag) + ": expected an integer in [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "], got \"" + std::string(*v) + "\"";
      return false;
    }
    *out = int(n);
    return true;
  };

  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      return o;
    } else if (arg == "--node-reference") {
      o.node_reference = true;
      return o;
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else if (arg == "-o" || arg == "--output") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      o.output = std::string(*v);
    } else if (arg == "--write-scene") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      o.write_scene = std::string(*v);
    } else if (arg == "--spp") {
      if (!int_option(i, arg, 1, 1 << 20, &o.spp)) return std::nullopt;
    } else if (arg == "--denoise") {
      o.denoise = true;
    } else if (arg == "--noise-threshold") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      double t = 0.0;
      if (!parse_number(*v, &t) || !(t > 0.0) || t > 10.0) {
        *error = "--noise-threshold: expected a relative error in (0, 10], e.g. 0.01, got \"" +
                 std::string(*v) + "\"";
        return std::nullopt;
      }
      o.noise_threshold = t;
    } else if (arg == "--min-spp") {
      if (!int_option(i, arg, 2, 1 << 20, &o.min_spp)) return std::nullopt;
    } else if (arg == "--threads") {
      if (!int_option(i, arg, 1, 1024, &o.threads)) return std::nullopt;
    } else if (arg == "--width") {
      if (!int_option(i, arg, 1, 16384, &o.width)) return std::nullopt;
    } else if (arg == "--height") {
      if (!int_option(i, arg, 1, 16384, &o.height)) return std::nullopt;
    } else if (arg == "--seed") {
      if (!int_option(i, arg, 0, 2147483647, &o.seed)) return std::nullopt;
    } else if (arg == "--time") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      double t = 0.0;
      if (!parse_number(*v, &t) || t < 0.0 || t > 1e7) {
        *error = "--time: expected seconds in [0, 1e7], got \"" + std::string(*v) + "\"";
        return std::nullopt;
      }
      o.time_seconds = t;
    } else if (arg == "--memory-limit") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      o.memory_limit = parse_size(*v);
      if (!o.memory_limit) {
        *error = "--memory-limit: expected a size such as 8G, 512M or 1000000000 (bytes), got \"" +
                 std::string(*v) + "\"";
        return std::nullopt;
      }
    } else if (arg == "--aov") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      const size_t eq = v->find('=');
      const std::string_view name = v->substr(0, eq);
      if ((eq != std::string_view::npos && eq + 1 == v->size()) || !aov_from_name(name)) {
        *error = "--aov: expected NAME=FILE with NAME one of " + aov_name_list() + "; got \"" +
                 std::string(*v) + "\"";
        return std::nullopt;
      }
      o.aovs.push_back(
          {std::string(name), eq == std::string_view::npos ? "" : std::string(v->substr(eq + 1))});
    } else if (arg == "--samples") {
      int a = 0, b = 0;
      std::optional<int> value;
      if (!int_option(i, arg, 0, 1 << 20, &value)) return std::nullopt;
      a = *value;
      if (!int_option(i, arg, 1, 1 << 20, &value)) return std::nullopt;
      b = *value;
      if (b <= a) {
        *error = "--samples A B: B must be above A (samples A to B, B excluded), got " + std::to_string(a) +
                 " " + std::to_string(b);
        return std::nullopt;
      }
      o.samples = {uint32_t(a), uint32_t(b)};
    } else if (arg == "--crop") {
      int c[4];
      for (int k = 0; k < 4; ++k) {
        std::optional<int> value;
        if (!int_option(i, arg, 0, 16384, &value)) return std::nullopt;
        c[k] = *value;
      }
      if (c[2] <= c[0] || c[3] <= c[1]) {
        *error = "--crop X0 Y0 X1 Y1: the window needs X1 > X0 and Y1 > Y0 (X1, Y1 excluded), got " +
                 std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + " " +
                 std::to_string(c[3]);
        return std::nullopt;
      }
      o.crop = PixelWindow{c[0], c[1], c[2], c[3]};
    } else if (arg == "--checkpoint") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      double m = 0.0;
      if (!parse_number(*v, &m) || m <= 0.0 || m > 1e6) {
        *error = "--checkpoint: expected minutes above 0, got \"" + std::string(*v) + "\"";
        return std::nullopt;
      }
      o.checkpoint_minutes = m;
    } else if (arg == "--resume") {
      o.resume = true;
    } else if (arg == "--decide-lines" || arg == "--line-decisions") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      (arg == "--decide-lines" ? o.decide_lines : o.line_decisions) = std::string(*v);
    } else if (arg == "--frames") {
      const auto v = value_of(i, arg);
      if (!v) return std::nullopt;
      o.frames = parse_frame_range(*v);
      if (!o.frames) {
        *error =
            "--frames: expected FIRST-LAST[:STEP] (LAST not below FIRST, STEP at least 1), a frame or "
            "\"all\"; got \"" +
            std::string(*v) + "\"";
        return std::nullopt;
      }
    } else if (!arg.empty() && arg[0] == '-') {
      *error = "unknown option \"" + std::string(arg) + "\" (see --help)";
      return std::nullopt;
    } else if (o.scene.empty()) {
      o.scene = std::string(arg);
    } else {
      *error = "unexpected argument \"" + std::string(arg) + "\": only one scene file is rendered";
      return std::nullopt;
    }
  }
  if (o.scene.empty()) {
    *error = "no scene file given (usage: inkray-render SCENE.json -o OUT.png; see --help)";
    return std::nullopt;
  }
  if (!o.write_scene.empty()) {
    if (!o.output.empty() || !o.aovs.empty() || o.samples || o.crop || o.frames || o.checkpoint_minutes ||
        o.resume) {
      *error = "--write-scene writes a scene and renders nothing: leave out -o, --aov and the render options";
      return std::nullopt;
    }
    return o;
  }
  if (!o.decide_lines.empty()) {
    if (!o.output.empty() || !o.aovs.empty() || o.samples || o.crop || o.frames || o.checkpoint_minutes ||
        o.resume || o.spp || !o.line_decisions.empty()) {
      *error =
          "--decide-lines writes line decisions and renders nothing: leave out -o, --aov, --spp and the "
          "other render options (--width, --height, --seed, --threads and --time apply)";
      return std::nullopt;
    }
    if (std::string problem = check_outputs({{"--decide-lines " + o.decide_lines.string(), o.decide_lines}});
        !problem.empty()) {
      *error = std::move(problem);
      return std::nullopt;
    }
    return o;
  }
  if (!o.line_decisions.empty() && !o.samples) {
    *error = "--line-decisions is read by a slice of samples: add --samples A B";
    return std::nullopt;
  }
  if (o.output.empty()) {
    *error = "no output file given: add -o OUT.png (or .pfm, .exr)";
    return std::nullopt;
  }
  if (o.min_spp && !o.noise_threshold) {
    *error = "--min-spp is the floor of adaptive sampling: add --noise-threshold";
    return std::nullopt;
  }
  if (o.samples) {
    if (o.noise_threshold) {
      *error =
          "--noise-threshold decides from all of a pixel's samples; a slice (--samples) has only some of "
          "them: adaptive sampling is for renders on one machine";
      return std::nullopt;
    }
    if (o.spp) {
      *error = "--samples A B says which samples to render: leave out --spp";
      return std::nullopt;
    }
    if (image_format_of(o.output) != ImageFormat::exr) {
      *error = "--samples writes a partial render, an OpenEXR file: -o must end in .exr, got \"" +
               o.output.string() + "\"";
      return std::nullopt;
    }
  }
  for (const auto& a : o.aovs) {
    if (o.samples && !a.file.empty()) {
      *error = "--aov " + a.name + "=" + a.file.string() +
               ": with --samples the AOV's sums go into the partial; "
               "give only --aov " +
               a.name + " and name its file to inkray-merge";
      return std::nullopt;
    }
    if (!o.samples && a.file.empty()) {
      *error = "--aov " + a.name + ": expected NAME=FILE (a NAME alone is for partials, with --samples)";
      return std::nullopt;
    }
  }
  // More than one frame into one file would overwrite it frame after frame.
  const bool many_frames = o.frames && (o.frames->all || o.frames->last > o.frames->first);
  if (many_frames) {
    if (!has_frame_pattern(o.output)) {
      *error =
          "--frames renders several frames: -o needs a run of '#' for the frame number (e.g. out_####.png), "
          "got \"" +
          o.output.string() + "\"";
      return std::nullopt;
    }
    for (const auto& a : o.aovs)
      if (!a.file.empty() && !has_frame_pattern(a.file)) {
        *error = "--frames renders several frames: --aov " + a.name + "=" + a.file.string() +
                 " needs a run of '#' for the frame number";
        return std::nullopt;
      }
  }
  // Every frame's files must differ from every other frame's, or one would overwrite another.
  if (o.frames && !o.frames->all)
    if (std::string problem = check_frame_names(o, frames_of(*o.frames)); !problem.empty()) {
      *error = "--frames " + std::to_string(o.frames->first) + "-" + std::to_string(o.frames->last) + ": " +
               problem;
      return std::nullopt;
    }
  // Every output is checked before the render, so a bad path costs no render time
  // (for frames, as the first frame names them: the folders are those of every frame).
  const int frame = o.frames && !o.frames->all ? o.frames->first : 0;
  std::vector<PlannedOutput> outputs = {{"-o " + o.output.string(), expand_frame_pattern(o.output, frame)}};
  if (o.denoise && !o.samples)
    outputs.push_back({"--denoise's raw image " + raw_image_path(o.output).string(),
                       expand_frame_pattern(raw_image_path(o.output), frame)});
  for (const auto& a : o.aovs)
    if (!a.file.empty())
      outputs.push_back({"--aov " + a.name + "=" + a.file.string(), expand_frame_pattern(a.file, frame)});
  for (const auto& planned : outputs) {
    if (image_format_of(planned.file) == ImageFormat::unknown) {
      *error = planned.file.string() + ": unknown image format (expected .png, .pfm or .exr)";
      return std::nullopt;
    }
  }
  if (std::string problem = check_outputs(outputs); !problem.empty()) {
    *error = std::move(problem);
    return std::nullopt;
  }
  return o;
}

}  // namespace inkray
