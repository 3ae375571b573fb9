// The node editor's add menu: node types grouped by category, or, once something is
// typed, the types whose names contain it (Enter takes the first). Drawn inside a popup
// the caller has begun; it adds nothing itself.
#pragma once

#include <string>

namespace inkray {

// The chosen type name, or "" while none is. `filter` is the search text, kept by the
// caller between frames; an output node is offered only when the graph has none.
std::string node_add_menu(std::string* filter, bool graph_has_output);

}  // namespace inkray
