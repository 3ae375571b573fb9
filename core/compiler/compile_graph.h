// Material graph compilation (docs/architecture.md, "Material graphs"): checks a
// GraphDesc (unknown sockets, dangling links, type mismatches, cycles), then
// lowers the nodes that reach the output to a flat ShaderProgram: constants
// folded, instructions in dependency order, registers reused once dead.
#pragma once

#include "core/compiler/asset_cache.h"
#include "core/document/desc.h"
#include "core/materials/material.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// Compiles a closure node's settings (a plain material description) into the
// template its per-hit inputs are copied over; defined by compile_materials.
std::optional<Material> compile_closure_template(const MaterialVariant& data,
                                                 const std::filesystem::path& base_dir, AssetCache& assets,
                                                 std::string* error);

// The program, or null with one message per problem appended to `errors`, each
// starting with the JSON path inside the material ("nodes[2] \"ramp\": ...",
// "links[0].input: ...").
std::shared_ptr<const ShaderProgram> compile_graph(const GraphDesc& graph,
                                                   const std::filesystem::path& base_dir, AssetCache& assets,
                                                   std::vector<std::string>& errors);

}  // namespace inkray
