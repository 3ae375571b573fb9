#include "app/render_cli.h"

#include "app/cli_numbers.h"
#include "app/cli_options.h"
#include "core/document/desc.h"
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
  --lines-svg FILE      also write the lines as an SVG file: each line a filled outline in its
                        style, a layer per line set (the outline types' colours without sets),
                        lines seen in mirrors and through glass included
  --lines-svg-image     put the image under the lines in the SVG (embedded as a PNG)
  --lines-pdf FILE      also write the lines as a one-page PDF file, a point per pixel
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
                        A run of '#' in -o, --aov and --lines-* files becomes the frame number, zero-padded
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
  if (!o.lines_svg.empty()) patterns.push_back({"--lines-svg " + o.lines_svg.string(), o.lines_svg});
  if (!o.lines_pdf.empty()) patterns.push_back({"--lines-pdf " + o.lines_pdf.string(), o.lines_pdf});
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

namespace {

using Options = RenderCliOptions;
using cli::Words;

// An option whose one word is a decimal number `ok` accepts, else `expected` is the message.
cli::Option<Options> decimal_option(std::string_view name, std::optional<double> Options::*member,
                                    bool (*ok)(double), std::string_view expected) {
  return {{name}, 1, [=](Options& o, Words w) {
            double value = 0.0;
            if (!parse_number(w[0], &value) || !ok(value))
              return std::string(name) + ": expected " + std::string(expected) + ", got \"" +
                     std::string(w[0]) + "\"";
            o.*member = value;
            return std::string();
          }};
}

// inkray-render's options; what they mean is kRenderCliHelp's. The ranges of --spp,
// --width, --height, --seed and --time are those of render.spp, .width, .height, .seed
// and .time_limit in RenderSettings' parameter table.
const std::vector<cli::Option<Options>>& render_options() {
  using cli::number_option, cli::param_range, cli::text_option, cli::flag_option;
  static const std::vector<cli::Option<Options>> table = {
      flag_option({"-h", "--help"}, &Options::help, true),
      flag_option({"--node-reference"}, &Options::node_reference, true),
      flag_option({"-q", "--quiet"}, &Options::quiet),
      text_option({"-o", "--output"}, &Options::output),
      text_option({"--write-scene"}, &Options::write_scene),
      number_option({"--spp"}, &Options::spp, param_range<int>(&RenderSettings::spp)),
      flag_option({"--denoise"}, &Options::denoise),
      text_option({"--lines-svg"}, &Options::lines_svg),
      text_option({"--lines-pdf"}, &Options::lines_pdf),
      flag_option({"--lines-svg-image"}, &Options::lines_svg_image),
      decimal_option(
          "--noise-threshold", &Options::noise_threshold, [](double t) { return t > 0.0 && t <= 10.0; },
          "a relative error in (0, 10], e.g. 0.01"),
      number_option({"--min-spp"}, &Options::min_spp, cli::Range<int>{2, 1 << 20}),
      number_option({"--threads"}, &Options::threads, cli::Range<int>{1, 1024}),
      number_option({"--width"}, &Options::width, param_range<int>(&RenderSettings::width)),
      number_option({"--height"}, &Options::height, param_range<int>(&RenderSettings::height)),
      number_option({"--seed"}, &Options::seed, param_range<int>(&RenderSettings::seed)),
      decimal_option(
          "--time", &Options::time_seconds,
          [](double t) {
            const auto r = param_range<double>(&RenderSettings::time_limit);
            return t >= r.lo && t <= r.hi;
          },
          "seconds in [0, 1e7]"),
      {{"--memory-limit"},
       1,
       [](Options& o, Words w) {
         o.memory_limit = parse_size(w[0]);
         return o.memory_limit
                    ? std::string()
                    : "--memory-limit: expected a size such as 8G, 512M or 1000000000 (bytes), got \"" +
                          std::string(w[0]) + "\"";
       }},
      {{"--aov"},
       1,
       [](Options& o, Words w) {
         const std::string_view v = w[0];
         const size_t eq = v.find('=');
         const std::string_view name = v.substr(0, eq);
         if ((eq != std::string_view::npos && eq + 1 == v.size()) || !aov_from_name(name))
           return "--aov: expected NAME=FILE with NAME one of " + aov_name_list() + "; got \"" +
                  std::string(v) + "\"";
         o.aovs.push_back(
             {std::string(name), eq == std::string_view::npos ? "" : std::string(v.substr(eq + 1))});
         return std::string();
       }},
      {{"--samples"},
       2,
       [](Options& o, Words w) {
         int a = 0, b = 0;
         for (std::string problem : {cli::read_option_number("--samples", w[0], 0, 1 << 20, &a),
                                     cli::read_option_number("--samples", w[1], 1, 1 << 20, &b)})
           if (!problem.empty()) return problem;
         if (b <= a)
           return "--samples A B: B must be above A (samples A to B, B excluded), got " + std::to_string(a) +
                  " " + std::to_string(b);
         o.samples = {uint32_t(a), uint32_t(b)};
         return std::string();
       }},
      {{"--crop"},
       4,
       [](Options& o, Words w) {
         int c[4];
         for (int k = 0; k < 4; ++k)
           if (std::string problem = cli::read_option_number("--crop", w[size_t(k)], 0, 16384, &c[k]);
               !problem.empty())
             return problem;
         if (c[2] <= c[0] || c[3] <= c[1])
           return "--crop X0 Y0 X1 Y1: the window needs X1 > X0 and Y1 > Y0 (X1, Y1 excluded), got " +
                  std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + " " +
                  std::to_string(c[3]);
         o.crop = PixelWindow{c[0], c[1], c[2], c[3]};
         return std::string();
       }},
      decimal_option(
          "--checkpoint", &Options::checkpoint_minutes, [](double m) { return m > 0.0 && m <= 1e6; },
          "minutes above 0"),
      flag_option({"--resume"}, &Options::resume),
      text_option({"--decide-lines"}, &Options::decide_lines),
      text_option({"--line-decisions"}, &Options::line_decisions),
      {{"--frames"},
       1,
       [](Options& o, Words w) {
         o.frames = parse_frame_range(w[0]);
         return o.frames ? std::string()
                         : "--frames: expected FIRST-LAST[:STEP] (LAST not below FIRST, STEP at least 1), a "
                           "frame or \"all\"; got \"" +
                               std::string(w[0]) + "\"";
       }},
  };
  return table;
}

}  // namespace

std::optional<RenderCliOptions> parse_render_cli(int argc, const char* const* argv, std::string* error) {
  RenderCliOptions o;
  *error =
      cli::parse_options<Options>(render_options(), argc, argv, o, [](Options& opts, std::string_view arg) {
        if (!opts.scene.empty())
          return "unexpected argument \"" + std::string(arg) + "\": only one scene file is rendered";
        opts.scene = std::string(arg);
        return std::string();
      });
  if (!error->empty()) return std::nullopt;
  if (o.help || o.node_reference) return o;
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
  if (o.samples && (!o.lines_svg.empty() || !o.lines_pdf.empty())) {
    *error = std::string(!o.lines_svg.empty() ? "--lines-svg" : "--lines-pdf") +
             ": a slice of samples (--samples) writes a partial, whose lines are drawn when the partials "
             "are merged: give it to inkray-merge";
    return std::nullopt;
  }
  if (o.lines_svg_image && o.lines_svg.empty()) {
    *error = "--lines-svg-image puts the image under the lines of --lines-svg FILE: add it";
    return std::nullopt;
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
    for (const auto& [option, file] :
         {std::pair{"--lines-svg", o.lines_svg}, std::pair{"--lines-pdf", o.lines_pdf}})
      if (!file.empty() && !has_frame_pattern(file)) {
        *error = "--frames renders several frames: " + std::string(option) + " " + file.string() +
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
  for (const auto& [option, file, extension] :
       {std::tuple{"--lines-svg", o.lines_svg, ".svg"}, std::tuple{"--lines-pdf", o.lines_pdf, ".pdf"}}) {
    if (file.empty()) continue;
    if (file.extension() != extension) {
      *error = std::string(option) + ": " + file.string() + ": expected a file ending in " + extension;
      return std::nullopt;
    }
    outputs.push_back({std::string(option) + " " + file.string(), expand_frame_pattern(file, frame)});
  }
  if (std::string problem = check_outputs(outputs); !problem.empty()) {
    *error = std::move(problem);
    return std::nullopt;
  }
  return o;
}

}  // namespace inkray
