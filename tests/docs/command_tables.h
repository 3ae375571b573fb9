// What the documented-commands test does to each command before running it: placeholders
// mapped to real files, commands it may leave out (each with its reason), and the rewrites
// that shrink a render to seconds. Every entry here is one the docs need; a stale one fails
// DocCommands.EveryTableEntryIsUsed.
#pragma once

#include <string_view>

namespace inkray::doc_commands {

// Words the docs use for "your file" or "a number", and what stands in for them. A command
// with a metavariable not listed here (FILE, OUT, PARTIAL...) fails the test until it is
// mapped here or its command is skipped below.
struct Placeholder {
  std::string_view word, replacement, why;
};
inline constexpr Placeholder kPlaceholders[] = {
    {"SCENE", "scenes/cornell_outlines.json", "any scene; one with lines runs the most code"},
    {"SCENE.json", "scenes/cornell_outlines.json", "any scene; one with lines runs the most code"},
    {"shot.json", "tests/data/farm/anim12.json",
     "a shot of 12 frames (tests/farm's), so --frames all is short"},
    {"scene.json", "scenes/animation.json",
     "docs/final-renders.md's shot: 960x540 (its crop windows are its quarters), with lines"},
    {"still.json", "scenes/cornell.json", "a still"},
    {"OUT.png", "out.png", "an output file"},
    {"OUT.pfm", "out.pfm", "an output file"},
    {"OUT.json", "out.json", "an output file"},
    {"N", "2", "a count (frames, edits, runs, threads)"},
    {"RUNS", "1", "a count of runs"},
    {"S", "1", "seconds"},
    {"E", "0.05", "an adaptive-sampling error target"},
    {"KIND[,KIND...]", "camera", "the editor's kinds of edit to measure"},
    {"DIR", "cache", "a folder the command creates"},
};

// Commands not run here, matched by their text as the doc shows it (comment removed).
// `covered_by`, when set, must appear in tests/farm/farm_test.sh: the farm runs there, on a
// Slurm cluster of its own.
struct Skip {
  std::string_view command, reason, covered_by;
};
inline constexpr Skip kSkips[] = {
    {"scripts/run", "installs packages and builds; then renders README.md's `--spp 64` example", ""},
    {"scripts/test", "runs every test, this one included", ""},
    {"scripts/fuzz TARGET SECONDS", "builds build-fuzz/ with clang; inkray_tests replays the corpora", ""},
    {"scripts/fuzz TARGET SECONDS [LIBFUZZER_FLAGS]",
     "builds build-fuzz/ with clang; inkray_tests replays the corpora", ""},
    {"inkray-merge --denoise", "names an option in prose", ""},
    {"inkray-render --memory-limit", "names an option in prose", ""},
    {"inkray-render --time", "names an option in prose", ""},
    {"inkray-render --frames", "names an option in prose", ""},
    {"inkray --input-script FILE", "names an option in prose; the tests in tests/ui play input scripts", ""},
    {"inkray-line-decisions 2", "the first line of a line-decisions file, not a command", ""},
    {"inkray-merge OUT PARTIAL...", "a synopsis; README.md and docs/final-renders.md merge real partials",
     ""},
    {"inkray-merge OUT.(png|pfm|exr) PARTIAL.exr... [--aov NAME=FILE]... [--threads N] [-q]",
     "a synopsis; docs/final-renders.md merges real partials", ""},
    {"inkray-merge OUT.partial.exr PARTIAL.exr... [-q]", "a synopsis; merging in stages is in tests/app", ""},
    {"...", "stands for the tiles the example leaves out", ""},
    {"inkray-merge image.exr tile_*.exr", "needs every tile, and the example lists two of four", ""},
    {"inkray-render SCENE --frames F-F -o /shared/renders/shot_####.png --threads 4 -q",
     "runs in tests/farm: what an animation's array task runs", "--frames 1-12"},
    {"inkray-render SCENE --samples a b -o WORK/partials/samples_a-b.exr --threads 8 -q",
     "runs in tests/farm: what a still's slice task runs", "--slices 4"},
    {"inkray-render SCENE --decide-lines ...", "runs in tests/farm: the slices' line-decisions job",
     "line_decisions.bin"},
    {"scripts/slurm-local start", "runs in tests/farm: it starts a Slurm cluster", "\"${slurm[@]}\" start"},
    {"scripts/farm scenes/cornell_outlines.json -o /tmp/cornell.png --slices 4 --spp 64",
     "runs in tests/farm: it submits to the cluster started above", "--slices 4"},
    {"scripts/slurm-local stop", "runs in tests/farm: it stops the cluster", "\"${slurm[@]}\" stop"},
};

// How an option's value shrinks. The docs show renders of minutes; here a block takes
// seconds, and the rewrite is the same for every command of a block, so what one command
// writes still fits the next (a slice its merge, line decisions their slices).
enum class Rule {
  divide_samples,       // N -> ceil(N / 64): 1024 -> 16, 32 -> 1
  divide_sample_range,  // A B -> A/64 B/64: slices meeting end to end still do (512 1024 -> 8 16)
  divide_pixels,        // N -> N / 10, at least 16: a hundredth of the pixels
  divide_window,        // X0 Y0 X1 Y1 -> each / 10, as the image shrinks
  at_most,              // N -> min(N, value)
  set,                  // anything -> value
  two_frames,           // A-B[:STEP] -> A-min(B, A+STEP)[:STEP]; one frame and "all" stay
  add_flag,             // a flag (no value) added when absent
};

// `programs`: names separated by spaces. `option`: "--spp", or "#2" for the second
// positional argument. `when_absent`: added when the command lacks the option, "scene"
// meaning the scene's own value divided as the rule divides.
struct Rewrite {
  std::string_view programs, option;
  Rule rule;
  std::string_view value, when_absent, why;
};
inline constexpr Rewrite kRewrites[] = {
    {"inkray-render inkray-bench-final", "--width", Rule::divide_pixels, "", "scene", "pixels cost time"},
    {"inkray-render inkray-bench-final", "--height", Rule::divide_pixels, "", "scene", "pixels cost time"},
    {"inkray-bench-coherence", "--width", Rule::divide_pixels, "", "", "pixels cost time"},
    {"inkray-bench-coherence", "--height", Rule::divide_pixels, "", "", "pixels cost time"},
    {"inkray-render", "--crop", Rule::divide_window, "", "", "the window shrinks with the image"},
    {"inkray-render inkray-bench-outlines inkray-bench-coherence inkray-bench-final", "--spp",
     Rule::divide_samples, "", "", "samples cost time"},
    {"inkray-render", "--samples", Rule::divide_sample_range, "", "",
     "every range of a block divides alike, so slices still merge"},
    {"inkray-bench-final", "--frame-spp", Rule::divide_samples, "", "", "its frames stay 960x540"},
    {"inkray-bench-graphs", "#1", Rule::divide_samples, "", "", "its first argument is spp"},
    {"inkray-bench-graphs", "#2", Rule::set, "1", "", "its second argument is runs"},
    {"inkray-bench-export", "#2", Rule::divide_samples, "", "", "its second argument is spp"},
    {"inkray-bench-export", "#3", Rule::set, "1", "", "its third argument is runs"},
    {"inkray-bench-export", "#4", Rule::divide_pixels, "", "scene", "its size, 800x450 if absent"},
    {"inkray-bench-export", "#5", Rule::divide_pixels, "", "scene", "height"},
    {"inkray-render", "--time", Rule::at_most, "2", "",
     "2 s still ends the render at its deadline, where --denoise once wrote nothing"},
    {"inkray-bench", "--time", Rule::at_most, "0.25", "", "it renders full size, with no --width"},
    {"inkray-bench", "--reference-spp", Rule::set, "1", "", "its reference is full size too"},
    {"inkray-bench", "--no-scaling", Rule::add_flag, "", "",
     "its thread-scaling table renders the full-size scene four more times, through the same passes"},
    {"inkray-bench", "--threads", Rule::set, "1", "1",
     "its bare-Embree probe takes 3 s whatever the scene: on one core CTest runs a test beside it"},
    {"inkray-render inkray-merge inkray-bench-outlines inkray-bench-strokes inkray-bench-coherence "
     "inkray-bench-final inkray",
     "--threads", Rule::set, "2", "", "CI has 2 cores"},
    {"inkray-render", "--frames", Rule::two_frames, "", "", "two frames show the pattern and the range"},
    {"inkray-bench-coherence inkray-bench-final", "--frames", Rule::at_most, "2", "", "a count of frames"},
    {"inkray-bench-outlines inkray-bench-lines", "--runs", Rule::set, "1", "1", "one run prints the table"},
    {"inkray-bench-bands", "--reference-spp", Rule::set, "4", "4", "its reference takes 1024 samples"},
    {"inkray-bench-bands", "--width", Rule::set, "32", "32", "pixels cost time"},
    {"inkray-bench-bands", "--height", Rule::set, "18", "18", "pixels cost time"},
    {"inkray-bench-strokes", "--counts", Rule::set, "0,1000", "0,1000", "100,000 strokes take seconds"},
    {"inkray-bench-strokes", "--passes", Rule::set, "1", "1", "one pass a row"},
    {"inkray-bench-strokes", "--repeats", Rule::set, "1", "1", "one repeat a row"},
    {"inkray", "--measure-edits", Rule::at_most, "2", "", "two edits of each kind"},
    {"inkray", "--frames", Rule::at_most, "3", "", "the screenshot follows the first full image anyway"},
};

// Rules for a whole command, in command_plan.h:
// - A render the doc bounds by --time alone (no --spp) gets --spp 1000000: at a hundredth of
//   the pixels the scene's own spp would end it long before its time, while at full size the
//   time ends it, and what happens then (denoising, writing) is what the doc shows.
// - valgrind in front of a command is dropped: the command is tested, not the profiler.
// - The editor runs under xvfb-run (the doc's own xvfb-run replaced) at 1280x720, with its
//   own config folder, and takes a screenshot and exits unless it prints --help or measures
//   edits (which end by themselves).
// - scripts/farm runs with --dry-run and --bin BUILD/bin: it checks every argument and
//   writes the job scripts' text, submitting nothing; tests/farm submits to a cluster.
// - `[optional]` parts of a synopsis are filled in: brackets removed, placeholders mapped.

}  // namespace inkray::doc_commands
