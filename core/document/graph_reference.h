// The node reference of docs/scene-format.md, written from the node types'
// parameter lists and socket declarations (graph_nodes.h), so the documentation
// cannot drift from the code: `inkray-render --node-reference` prints it,
// scripts/update-node-docs puts it in the document, and a test compares.
#pragma once

#include <string>

namespace inkray {

std::string node_reference_markdown();

}  // namespace inkray
