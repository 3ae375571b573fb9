// Fuzz harness for material graph compilation, structure-aware: the input picks one of
// the example scenes' graphs and drives a sequence of the node editor's own edits on it
// (tests/compiler/graph_edit_ops.h), then compiles. The graph must compile to a program
// whose values are finite at any hit, or be refused with messages; a graph that compiles
// must be written, read back and written again to the same text.
#include "tests/compiler/graph_edit_ops.h"
#include "tests/fuzz/fuzz_targets.h"

#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

const std::filesystem::path kSource = INKRAY_SOURCE_DIR;
// The edits' image paths (graph_edit_ops.h) resolve here.
const std::filesystem::path kBase = kSource / "tests" / "data" / "scenes" / "valid";

// Enough edits to build any small graph; each takes a few bytes.
constexpr int kMaxEdits = 256;

}  // namespace

int fuzz_graph_compile(const std::uint8_t* data, std::size_t size) {
  static const std::vector<GraphDesc> starts = graph_ops::example_graphs(kSource);
  static AssetCache assets;  // the few images the edits name, decoded once
  graph_ops::ByteStream in(data, size);
  GraphDesc g = starts[in.pick(starts.size())];
  try {
    for (int k = 0; k < kMaxEdits && !in.empty(); ++k) graph_ops::apply_edit(g, in);
  } catch (const std::exception& e) {
    fuzz_fail(std::string("an edit threw: ") + e.what());
  }
  const graph_ops::CompileOutcome c = graph_ops::compile_and_check(g, kBase, assets);
  if (!c.problem.empty()) fuzz_fail(c.problem);
  if (c.program) {
    const std::string problem = graph_ops::round_trip_problem(g, kBase);
    if (!problem.empty()) fuzz_fail(problem);
  }
  return 0;
}

}  // namespace inkray
