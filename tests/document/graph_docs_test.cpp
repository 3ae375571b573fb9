// The node reference in docs/scene-format.md is the one the node types' parameter
// lists generate: a node or parameter added, renamed or redocumented fails here
// until scripts/update-node-docs writes it into the document.
#include "core/document/graph_reference.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace inkray {
namespace {

TEST(GraphDocs, NodeReferenceIsCurrent) {
  std::ifstream in(INKRAY_SOURCE_DIR "/docs/scene-format.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- node-reference:begin -->\n", end = "<!-- node-reference:end -->";
  const size_t b = doc.find(begin), e = doc.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  EXPECT_EQ(doc.substr(b + begin.size(), e - b - begin.size()), node_reference_markdown())
      << "the node reference in docs/scene-format.md is stale: run scripts/update-node-docs";
}

}  // namespace
}  // namespace inkray
