// Graph edits as the node editor commits them, through the document's undo stack: a
// drag is one step, every step undoes and redoes exactly, node positions are layout
// (nothing recompiles) and a node's value is that material's edit alone.
#include "core/document/graph_edit.h"
#include "core/document/json_io.h"
#include "core/document/stage_diff.h"
#include "support/render_helpers.h"
#include "ui/model/document.h"

#include <gtest/gtest.h>

#include <map>

namespace inkray {
namespace {

SceneDesc graph_scene() {
  SceneLoadResult loaded = load_scene(INKRAY_SOURCE_DIR "/scenes/graph_toon_rim.json", ReadFor::editing);
  EXPECT_TRUE(loaded.scene);
  return *loaded.scene;
}

size_t graph_index(const SceneDesc& s) {
  for (size_t i = 0; i < s.materials.size(); ++i)
    if (std::holds_alternative<GraphDesc>(s.materials[i].data)) return i;
  ADD_FAILURE() << "no graph material";
  return 0;
}

// One committed graph edit, as NodeEditorPanel::commit makes it.
void commit(Document& doc, const std::function<void(GraphDesc&)>& change, const std::string& label,
            const std::string& merge_key = {}) {
  SceneDesc s = doc.scene();
  change(std::get<GraphDesc>(s.materials[graph_index(s)].data));
  doc.edit(std::move(s), label, merge_key);
}

TEST(GraphUndo, EveryEditUndoesAndRedoesExactly) {
  Document doc;
  doc.reset(graph_scene());
  std::vector<SceneDesc> states = {doc.scene()};
  commit(
      doc, [](GraphDesc& g) { add_node(g, "noise_texture", -200.f, 0.f); }, "Add noise");
  states.push_back(doc.scene());
  commit(
      doc, [](GraphDesc& g) { ASSERT_FALSE(connect(g, "noise_texture", "fac", "rim_mask", "b")); }, "Link");
  states.push_back(doc.scene());
  // A drag: many moves under one merge key are one step.
  for (int i = 0; i < 10; ++i)
    commit(
        doc, [](GraphDesc& g) { move_nodes(g, {"toon"}, 3.f, 1.f); }, "Move", "graph-move:facing_toon_rim");
  doc.end_merge();
  states.push_back(doc.scene());
  commit(
      doc, [](GraphDesc& g) { remove_nodes(g, {"fresnel"}); }, "Delete");
  states.push_back(doc.scene());
  EXPECT_EQ(doc.history().size(), 4u) << "the drag is one undo step";

  for (size_t i = states.size() - 1; i > 0; --i) {
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene(), states[i - 1]) << "undo to state " << i - 1;
  }
  for (size_t i = 1; i < states.size(); ++i) {
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene(), states[i]) << "redo to state " << i;
  }
}

TEST(GraphUndo, PositionsAreLayoutAndValuesAreThatMaterialsEdit) {
  const SceneDesc before = graph_scene();
  SceneDesc moved = before;
  GraphDesc& g = std::get<GraphDesc>(moved.materials[graph_index(moved)].data);
  move_nodes(g, {"toon", "rim"}, 40.f, -12.f);
  g.editor.zoom = 0.75f;
  EXPECT_EQ(changed_stages(before, moved).names(), "layout");

  SceneDesc valued = before;
  GraphDesc& v = std::get<GraphDesc>(valued.materials[graph_index(valued)].data);
  for (GraphNodeDesc& n : v.nodes)
    if (auto* f = std::get_if<FresnelNode>(&n.data)) f->ior = 1.8f;
  EXPECT_EQ(changed_stages(before, valued).names(), "material");
}

// The four example looks can be built with the editor's operations alone: from an
// empty material, add each node from the menu, set its values, link it, and the
// material renders as the example file does.
TEST(GraphBuild, EveryExampleLookIsBuiltWithTheEditorsOperations) {
  for (const char* file : {"graph_toon_rim.json", "graph_painterly.json", "graph_xtoon_depth.json",
                           "graph_outline_gradient.json"}) {
    SCOPED_TRACE(file);
    SceneLoadResult loaded = load_scene(std::string(INKRAY_SOURCE_DIR "/scenes/") + file);
    ASSERT_TRUE(loaded.scene);
    SceneDesc example = *loaded.scene;
    example.render.width = 48;
    example.render.height = 27;
    for (StrokeEmitterDesc& e : example.strokes) e.count = std::min(e.count, 200);
    SceneDesc built = example;
    for (MaterialDesc& m : built.materials) {
      const auto* target = std::get_if<GraphDesc>(&m.data);
      if (!target) continue;
      // A new material starts as a diffuse; "Edit nodes" shows it as a graph, whose
      // closure the artist deletes to start from the output alone.
      GraphDesc g = graph_from_material(DiffuseDesc{});
      std::vector<std::string> start;
      std::string output;
      for (const GraphNodeDesc& n : g.nodes) {
        start.push_back(n.id);
        if (std::holds_alternative<OutputNode>(n.data)) output = n.id;
      }
      remove_nodes(g, start);
      ASSERT_EQ(g.nodes.size(), 1u) << "the output stays";
      std::map<std::string, std::string> id_of;
      float y = 0.f;
      for (const GraphNodeDesc& n : target->nodes) {
        const bool is_output = std::holds_alternative<OutputNode>(n.data);
        const std::string id = is_output ? output : add_node(g, node_type_name(n.data), 0.f, y += 80.f);
        ASSERT_FALSE(id.empty()) << node_type_name(n.data);
        for (GraphNodeDesc& added : g.nodes)
          if (added.id == id) added.data = n.data;  // the node's widgets
        id_of[n.id] = id;
      }
      for (const GraphLinkDesc& l : target->links)
        ASSERT_EQ(connect(g, id_of[l.from], l.output, id_of[l.to], l.input), std::nullopt)
            << l.from << " -> " << l.to;
      m.data = g;
    }
    const RgbImage want = testing::render_scene(example, 2);
    const RgbImage got = testing::render_scene(built, 2);
    ASSERT_EQ(want.pixels.size(), got.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < want.pixels.size(); ++i)
      differing += glm::any(glm::greaterThan(glm::abs(want.pixels[i] - got.pixels[i]), Vec3(1e-5f)));
    EXPECT_EQ(differing, 0u);
  }
}

}  // namespace
}  // namespace inkray
