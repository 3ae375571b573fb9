// Random sequences of the node editor's own edits (graph_edit.h, and values set as the
// widgets set them), compiled after every one: a graph compiles to a program whose
// values are finite at any hit, or is refused with messages; never a crash. A graph
// that compiles is saved and opened again unchanged.
#include "tests/compiler/graph_edit_ops.h"

#include <gtest/gtest.h>

#include <random>

namespace inkray {
namespace {

const std::filesystem::path kSource = INKRAY_SOURCE_DIR;
const std::filesystem::path kBase = kSource / "tests" / "data" / "scenes" / "valid";

TEST(GraphEdits, TenThousandRandomEditsCompileOrAreRefusedWithMessages) {
  constexpr int kSteps = 10000;
  constexpr int kStepsPerStart = 500;  // then the next example graph, so the graph never drifts far
  const std::vector<GraphDesc> starts = graph_ops::example_graphs(kSource);
  ASSERT_FALSE(starts.empty());
  std::mt19937 rng(20261205u);
  std::vector<std::uint8_t> bytes(size_t(kSteps) * 64);
  for (std::uint8_t& b : bytes) b = std::uint8_t(rng());
  graph_ops::ByteStream in(bytes.data(), bytes.size());
  AssetCache assets;
  GraphDesc g;
  int compiled = 0, refused = 0;
  for (int step = 0; step < kSteps; ++step) {
    if (step % kStepsPerStart == 0) g = starts[size_t(step / kStepsPerStart) % starts.size()];
    ASSERT_NO_THROW(graph_ops::apply_edit(g, in)) << "step " << step;
    const graph_ops::CompileOutcome c = graph_ops::compile_and_check(g, kBase, assets);
    ASSERT_EQ(c.problem, "") << "step " << step << "\n"
                             << copy_nodes(g, [&] {
                                  std::vector<std::string> ids;
                                  for (const GraphNodeDesc& n : g.nodes) ids.push_back(n.id);
                                  return ids;
                                }());
    (c.program ? compiled : refused) += 1;
    // Saving and opening again is dearer than compiling: every tenth compiled graph.
    if (c.program && compiled % 10 == 0) {
      ASSERT_EQ(graph_ops::round_trip_problem(g, kBase), "") << "step " << step;
    }
  }
  // Both outcomes are exercised: the edits make valid graphs and broken ones.
  EXPECT_GT(compiled, kSteps / 10);
  EXPECT_GT(refused, 0);
  RecordProperty("compiled", compiled);
  RecordProperty("refused", refused);
}

}  // namespace
}  // namespace inkray
