// Turns one documented command into what the test runs: placeholders mapped, values shrunk
// by command_tables.h, executables resolved to the build, and the files it must write.
#pragma once

#include "core/document/json_io.h"
#include "tests/docs/command_tables.h"
#include "tests/docs/doc_commands.h"
#include "tests/support/messages.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace inkray::doc_commands {

// What one documented line becomes.
struct CommandPlan {
  std::string program;               // "inkray-render", "scripts/farm", "mkdir"
  std::vector<std::string> words;    // as run, program path first, wrappers not included
  std::string shell;                 // the whole command line, wrappers included
  std::vector<std::string> outputs;  // files (relative to the block's folder) it must leave, non-empty
  std::string skip;                  // set: not run, and why
  std::string error;                 // set: the test cannot run it, and why (the test fails)
  bool editor = false, farm = false;
};

// The values each option takes, for every inkray program; flags not listed take none.
inline int option_arity(const std::string& option) {
  static const std::map<std::string, int> arity = {{"--samples", 2},       {"--window-size", 2},
                                                   {"--crop", 4},          {"-o", 1},
                                                   {"--output", 1},        {"--spp", 1},
                                                   {"--time", 1},          {"--memory-limit", 1},
                                                   {"--threads", 1},       {"--width", 1},
                                                   {"--height", 1},        {"--seed", 1},
                                                   {"--aov", 1},           {"--noise-threshold", 1},
                                                   {"--min-spp", 1},       {"--write-scene", 1},
                                                   {"--frames", 1},        {"--checkpoint", 1},
                                                   {"--decide-lines", 1},  {"--line-decisions", 1},
                                                   {"--reference-spp", 1}, {"--cache", 1},
                                                   {"--adaptive", 1},      {"--runs", 1},
                                                   {"--counts", 1},        {"--passes", 1},
                                                   {"--repeats", 1},       {"--scenes", 1},
                                                   {"--build-threads", 1}, {"--row", 1},
                                                   {"--frame-spp", 1},     {"--frame-scene", 1},
                                                   {"--slices", 1},        {"--screenshot", 1},
                                                   {"--measure-edits", 1}, {"--edit", 1},
                                                   {"--select", 1},        {"--export", 1},
                                                   {"--drop", 1},          {"--input-script", 1},
                                                   {"--scene-dump", 1},    {"--ui-scale", 1},
                                                   {"--cpus-per-task", 1}, {"--mem", 1},
                                                   {"--chunk", 1},         {"--tiles", 1},
                                                   {"--bin", 1},           {"--partition", 1}};
  const auto it = arity.find(option);
  return it == arity.end() ? 0 : it->second;
}

// A command as options with their values and positional arguments, in order.
struct Argument {
  std::string option;  // empty for a positional argument
  std::vector<std::string> values;
};

inline std::vector<Argument> parse_arguments(const std::vector<std::string>& words) {
  std::vector<Argument> args;
  for (size_t i = 1; i < words.size(); ++i) {
    if (words[i].size() > 1 && words[i][0] == '-' && !std::isdigit(static_cast<unsigned char>(words[i][1]))) {
      Argument a{words[i], {}};
      const int arity = option_arity(words[i]);
      for (int k = 0; k < arity && i + 1 < words.size(); ++k) a.values.push_back(words[++i]);
      args.push_back(std::move(a));
    } else {
      args.push_back({"", {words[i]}});
    }
  }
  return args;
}

inline Argument* find_option(std::vector<Argument>& args, const std::string& option) {
  if (option[0] == '#') {
    int n = std::stoi(option.substr(1));
    for (Argument& a : args)
      if (a.option.empty() && --n == 0) return &a;
    return nullptr;
  }
  for (Argument& a : args)
    if (a.option == option) return &a;
  return nullptr;
}
inline const Argument* find_option(const std::vector<Argument>& args, const std::string& option) {
  return find_option(const_cast<std::vector<Argument>&>(args), option);
}

inline bool lists_program(std::string_view programs, const std::string& program) {
  std::istringstream names{std::string(programs)};
  for (std::string name; names >> name;)
    if (name == program) return true;
  return false;
}

// A word that stands for something the reader fills in: N, FILE, OUT.png, F-F,
// WORK/partials/x, PARTIAL.exr..., OUT.(png|pfm|exr). Checked after mapping.
inline bool is_metavariable(const std::string& word) {
  static const std::regex upper(R"([A-Z][A-Z0-9_-]*(\.[A-Za-z]+)?)");
  if (word.find("...") != std::string::npos || word.find_first_of("[]|()<>") != std::string::npos)
    return true;
  std::string value = word.substr(word.find('=') == std::string::npos ? 0 : word.find('=') + 1);
  std::istringstream parts(value);
  for (std::string part; std::getline(parts, part, '/');)
    if (std::regex_match(part, upper)) return true;
  return false;
}

inline std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// The scene named by the first positional argument, read for its size and frames.
inline std::optional<SceneDesc> scene_of(const std::vector<Argument>& args, std::string* error) {
  const Argument* scene = find_option(args, "#1");
  if (!scene) return *error = "no scene argument to read the size from", std::nullopt;
  SceneLoadResult loaded = load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / scene->values[0]);
  if (!loaded)
    return *error = "cannot read " + scene->values[0] + ": " + testing::joined(loaded.errors), std::nullopt;
  return loaded.scene;
}

// Applies one rule to an option's values; an empty string, or why it cannot.
inline std::string apply_rule(const Rewrite& r, std::vector<std::string>& values) {
  const size_t needed = r.rule == Rule::divide_sample_range ? 2 : r.rule == Rule::divide_window ? 4 : 1;
  if (values.size() < needed) return std::string(r.option) + " needs " + std::to_string(needed) + " values";
  try {
    switch (r.rule) {
      case Rule::divide_samples:
        values[0] = std::to_string(std::max(1L, (std::stol(values[0]) + 63) / 64));
        return {};
      case Rule::divide_sample_range: {
        const long a = std::stol(values[0]) / 64, b = std::stol(values[1]) / 64;
        if (b <= a) return "the range " + values[0] + " " + values[1] + " is empty after dividing by 64";
        values = {std::to_string(a), std::to_string(b)};
        return {};
      }
      case Rule::divide_pixels:
        values[0] = std::to_string(std::max(16L, std::lround(std::stod(values[0]) / 10.0)));
        return {};
      case Rule::divide_window:
        for (std::string& v : values) v = std::to_string(std::lround(std::stod(v) / 10.0));
        return {};
      case Rule::at_most:
        values[0] = format_number(std::min(std::stod(values[0]), std::stod(std::string(r.value))));
        return {};
      case Rule::set:
        values[0] = std::string(r.value);
        return {};
      case Rule::add_flag:
        return {};
      case Rule::two_frames: {
        static const std::regex range(R"((-?\d+)-(-?\d+)(:(\d+))?)");
        std::smatch m;
        if (!std::regex_match(values[0], m, range)) return {};  // one frame, or "all"
        const long a = std::stol(m[1]), step = m[4].matched ? std::stol(m[4]) : 1;
        values[0] = m[1].str() + "-" + std::to_string(std::min(std::stol(m[2]), a + step)) +
                    (m[3].matched ? m[3].str() : "");
        return {};
      }
    }
  } catch (const std::exception&) {
  }
  return "cannot apply the rewrite of " + std::string(r.option) + " to `" + values[0] + "`";
}

// Files named by a pattern with a run of '#': one per frame of `frames` (A-B[:STEP], N or
// "all", the scene's range); without a run, the name itself.
inline std::vector<std::string> expand_frames(const std::string& pattern, const std::string& frames,
                                              const SceneDesc* scene) {
  const size_t at = pattern.find('#');
  if (at == std::string::npos) return {pattern};
  const size_t run = pattern.find_first_not_of('#', at) - at;
  long first = scene ? scene->render.frame_start : 1, last = scene ? scene->render.frame_end : 1, step = 1;
  static const std::regex range(R"((-?\d+)(-(-?\d+))?(:(\d+))?)");
  std::smatch m;
  if (std::regex_match(frames, m, range)) {
    first = last = std::stol(m[1]);
    if (m[3].matched) last = std::stol(m[3]);
    if (m[5].matched) step = std::stol(m[5]);
  }
  std::vector<std::string> files;
  for (long f = first; f <= last; f += step) {
    std::string number = std::to_string(f);
    if (number.size() < run) number.insert(0, run - number.size(), '0');
    files.push_back(pattern.substr(0, at) + number + pattern.substr(at + run));
  }
  return files;
}

inline std::string raw_beside(const std::string& file) {
  const std::filesystem::path p(file);
  return (p.parent_path() / (p.stem().string() + "_raw" + p.extension().string())).string();
}

// The files a command says it writes.
inline std::vector<std::string> written_files(const std::string& program, const std::vector<Argument>& args) {
  std::vector<std::string> files;
  const Argument* frames = find_option(args, "--frames");
  std::string error;
  const std::optional<SceneDesc> scene =
      program == "inkray-render" && frames ? scene_of(args, &error) : std::nullopt;
  const auto add = [&](const std::string& pattern) {
    for (const std::string& f :
         expand_frames(pattern, frames ? frames->values[0] : "", scene ? &*scene : nullptr))
      files.push_back(f);
  };
  const bool denoise = find_option(args, "--denoise") && !find_option(args, "--samples");
  std::string image;
  if (program == "inkray-render") {
    for (const char* o : {"-o", "--output"})
      if (const Argument* a = find_option(args, o)) image = a->values[0];
    for (const char* o : {"--decide-lines", "--write-scene"})
      if (const Argument* a = find_option(args, o)) add(a->values[0]);
  } else if (program == "inkray-merge") {
    if (const Argument* a = find_option(args, "#1")) image = a->values[0];
  } else if (program == "inkray") {
    if (const Argument* a = find_option(args, "--screenshot")) add(a->values[0]);
  }
  if (!image.empty()) {
    add(image);
    if (denoise) add(raw_beside(image));
  }
  if (program == "inkray-render" || program == "inkray-merge")
    for (const Argument& a : args)
      if (a.option == "--aov" && a.values[0].find('=') != std::string::npos)
        add(a.values[0].substr(a.values[0].find('=') + 1));
  return files;
}

// Quoted for sh, globs left to it (tile_*.exr).
inline std::string shell_quote(const std::string& word) {
  static const std::regex plain(R"([A-Za-z0-9_./=:,+*-]+)");
  if (std::regex_match(word, plain)) return word;
  std::string q = "'";
  for (const char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string skip_reason(const std::string& text) {
  for (const Skip& s : kSkips)
    if (s.command == text) return std::string(s.reason);
  return {};
}

// `config_dir`: where the editor keeps its settings for this run.
inline CommandPlan plan_command(const DocLine& line, const std::filesystem::path& config_dir) {
  CommandPlan plan;
  if (std::string why = skip_reason(line.text); !why.empty()) return plan.skip = why, plan;
  if (!line.inkray) {
    if (!line.words.empty() && line.words[0] == "mkdir") {
      plan.program = "mkdir", plan.words = line.words;
      for (const std::string& w : line.words) plan.shell += (plan.shell.empty() ? "" : " ") + shell_quote(w);
      return plan;
    }
    return plan.error =
               "neither an inkray command nor one this test runs (map or skip it in "
               "tests/docs/command_tables.h)",
           plan;
  }
  // The program and its arguments, wrappers dropped, optional [parts] filled in, placeholders mapped.
  std::vector<std::string> words(line.words.begin() + std::ptrdiff_t(*program_index(line.words)),
                                 line.words.end());
  for (std::string& w : words) {
    if (w.size() > 1 && w.front() == '[') w.erase(0, 1);
    if (w.size() > 1 && w.back() == ']' && w.find('[') == std::string::npos) w.pop_back();
    for (const Placeholder& p : kPlaceholders)
      if (w == p.word) w = std::string(p.replacement);
  }
  for (const std::string& w : words)
    if (is_metavariable(w))
      return plan.error = "`" + w +
                          "` is a placeholder tests/docs/command_tables.h does not map; map it "
                          "in kPlaceholders or list the command in kSkips with a reason",
             plan;
  plan.program =
      words[0].rfind("scripts/", 0) == 0 ? words[0] : std::filesystem::path(words[0]).filename().string();
  plan.editor = plan.program == "inkray";
  plan.farm = plan.program == "scripts/farm";

  std::vector<Argument> args = parse_arguments(words);
  // A command that sets one side keeps the scene's aspect ratio: only a missing size is added.
  const bool own_size = find_option(args, "--width") || find_option(args, "--height");
  for (const Rewrite& r : kRewrites) {
    if (!lists_program(r.programs, plan.program)) continue;
    const std::string option(r.option);
    Argument* a = find_option(args, option);
    if (r.rule == Rule::add_flag) {
      if (!a) args.push_back({option, {}});
      continue;
    }
    if (!a && (r.when_absent.empty() || (r.when_absent == "scene" && own_size))) continue;
    if (!a) {
      std::vector<std::string> values = {std::string(r.when_absent)};
      if (r.when_absent == "scene") {
        std::string error;
        const std::optional<SceneDesc> scene = scene_of(args, &error);
        if (!scene) return plan.error = error, plan;
        const bool width = option == "--width" || option == "#4";
        values = {std::to_string(width ? scene->render.width : scene->render.height)};
        if (std::string why = apply_rule(r, values); !why.empty()) return plan.error = why, plan;
      }
      args.push_back(option[0] == '#' ? Argument{"", values} : Argument{option, values});
      continue;
    }
    if (std::string why = apply_rule(r, a->values); !why.empty()) return plan.error = why, plan;
  }
  if (plan.program == "inkray-render" && find_option(args, "--time") && !find_option(args, "--spp") &&
      !find_option(args, "--samples"))
    args.push_back({"--spp", {"1000000"}});
  if (plan.farm) {
    args.push_back({"--dry-run", {}});
    args.push_back({"--bin", {std::string(INKRAY_BINARY_DIR) + "/bin"}});
  }
  const bool ends_by_itself =
      find_option(args, "--help") || find_option(args, "-h") || find_option(args, "--measure-edits");
  if (plan.editor && !ends_by_itself && !find_option(args, "--screenshot")) {
    args.push_back({"--screenshot", {"editor_screenshot.png"}});
    if (!find_option(args, "--frames")) args.push_back({"--frames", {"3"}});
  }

  plan.words = {plan.program.rfind("scripts/", 0) == 0
                    ? std::string(INKRAY_SOURCE_DIR) + "/" + plan.program
                    : std::string(INKRAY_BINARY_DIR) + "/bin/" + plan.program};
  if (plan.editor) plan.words.insert(plan.words.end(), {"--window-size", "1280", "720"});
  for (const Argument& a : args) {
    if (!a.option.empty()) plan.words.push_back(a.option);
    plan.words.insert(plan.words.end(), a.values.begin(), a.values.end());
  }
  plan.outputs = written_files(plan.program, args);
  if (plan.editor)
    plan.shell = "env INKRAY_CONFIG_DIR=" + shell_quote(config_dir.string()) +
                 " xvfb-run -a -s '-screen 0 1280x720x24'";
  for (const std::string& w : plan.words) plan.shell += (plan.shell.empty() ? "" : " ") + shell_quote(w);
  return plan;
}

}  // namespace inkray::doc_commands
