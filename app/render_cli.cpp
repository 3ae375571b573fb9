#include "app/render_cli.h"

#include "core/film/film.h"
#include "core/image/image_io.h"
#include "core/io/output_set.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace inkray {

const char* const kRenderCliHelp = R"(inkray-render: render an inkray scene without a window.

usage: inkray-render SCENE.json -o OUT.(png|pfm|exr) [options]
       inkray-render SCENE.json --write-scene OUT.json


  -o, --output FILE     image to write; .png is 8-bit sRGB, .pfm and .exr are linear float
  --spp N               samples per pixel (default: the scene's render.spp)
  --time SECONDS        the whole run, reading and building the scene included, takes at most this
                        long (default: the scene's render.time_limit; 0 means no limit); the render
                        stops at whichever of --spp and --time comes first, and a scene that cannot
                        be built in time is an error that writes nothing
  --memory-limit SIZE   refuse a scene whose estimated memory is above SIZE (bytes, or with a K, M,
                        G or T suffix; default: half of this machine's memory)
  --threads N           worker threads (default: one per hardware thread)
  --width W --height H  override the scene's resolution (the aspect ratio follows)
  --seed S              seed of every random decision (default: the scene's render.seed)
  --aov NAME=FILE       also write an AOV; may be repeated. NAME is a first-hit AOV (albedo, normal,
                        depth, object_id, material_id) or an outline opacity: outline (all line
                        types) or outline_depth, outline_crease, outline_intersection,
                        outline_material, outline_object, outline_silhouette (one type each)
  --write-scene FILE    read and check the scene, write it as the editor saves it (every
                        parameter, asset paths relative to FILE's folder) and exit without
                        rendering; upgrades and normalises scene files
  -q, --quiet           no progress bar
  --node-reference      print the reference of material-graph nodes (Markdown), generated from
                        their parameter lists, and exit
  -h, --help            this text

The same scene, seed and sample count give the same image at any thread count.
After the render a table lists, per pass checkpoint, the samples per pixel, the elapsed
seconds and the estimated relative error (from the difference of even and odd passes).
Exit status: 0 on success, 1 on a scene or output error, 2 on bad arguments.
)";

namespace {

template <class T>
bool parse_number(std::string_view text, T* out) {
  const char* end = text.data() + text.size();
  if constexpr (std::is_floating_point_v<T>) {
    // std::from_chars for double is available in GCC 12.
    auto [ptr, ec] = std::from_chars(text.data(), end, *out);
    return ec == std::errc() && ptr == end && std::isfinite(*out);
  } else {
    auto [ptr, ec] = std::from_chars(text.data(), end, *out);
    return ec == std::errc() && ptr == end;
  }
}

// "8G", "512M", "64k", "1000000": bytes, at least 1 MiB and below 2^60.
std::optional<std::uint64_t> parse_size(std::string_view text) {
  int shift = 0;
  if (!text.empty()) {
    switch (text.back()) {
      case 'k': case 'K': shift = 10; break;
      case 'm': case 'M': shift = 20; break;
      case 'g': case 'G': shift = 30; break;
      case 't': case 'T': shift = 40; break;
      default: break;
    }
  }
  if (shift) text.remove_suffix(1);
  double value = 0.0;
  if (!parse_number(text, &value) || value <= 0.0) return std::nullopt;
  const double bytes = std::ldexp(value, shift);
  if (bytes < double(1 << 20) || bytes >= std::ldexp(1.0, 60)) return std::nullopt;
  return std::uint64_t(bytes);
}

}  // namespace

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
      *error = std::string(flag) + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
               "], got \"" + std::string(*v) + "\"";
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
      if (eq == std::string_view::npos || eq + 1 == v->size() || !aov_from_name(name)) {
        *error = "--aov: expected NAME=FILE with NAME one of " + aov_name_list() + "; got \"" +
                 std::string(*v) + "\"";
        return std::nullopt;
      }
      o.aovs.push_back({std::string(name), std::string(v->substr(eq + 1))});
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
    if (!o.output.empty() || !o.aovs.empty()) {
      *error = "--write-scene writes a scene and renders nothing: leave out -o and --aov";
      return std::nullopt;
    }
    return o;
  }
  if (o.output.empty()) {
    *error = "no output file given: add -o OUT.png (or .pfm, .exr)";
    return std::nullopt;
  }
  // Every output is checked before the render, so a bad path costs no render time.
  std::vector<PlannedOutput> outputs = {{"-o " + o.output.string(), o.output}};
  for (const auto& a : o.aovs) outputs.push_back({"--aov " + a.name + "=" + a.file.string(), a.file});
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
