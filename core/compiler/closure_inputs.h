// Where each valued input of a closure node lands in its compiled material
// (docs/architecture.md, "Material graphs"): a setter per socket, found by name. The
// toon closure's settings are set through the member pointers of ToonDesc's parameter
// table (its rows into ToonParams), so a new toon setting needs no line here.
#pragma once

#include "core/document/material_desc.h"
#include "core/materials/material.h"

#include <string_view>

namespace inkray {

// The setter of the valued input `socket` of a closure node of type `type` (its JSON
// "type", DiffuseDesc::type_name and the like); null when there is no such input
// (tests/compiler/closure_inputs_test.cpp checks every closure node's valued sockets
// have one).
ClosureSetter closure_input_setter(std::string_view type, std::string_view socket);

}  // namespace inkray
