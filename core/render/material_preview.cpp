#include "core/render/material_preview.h"

#include <set>

namespace inkray {
namespace {

// The material and everything it names, in document order (mixes refer by name).
std::vector<MaterialDesc> with_dependencies(const SceneDesc& doc, const std::string& name) {
  std::set<std::string> wanted = {name};
  for (bool grew = true; grew;) {
    grew = false;
    for (const MaterialDesc& m : doc.materials) {
      if (!wanted.count(m.name)) continue;
      if (const auto* mix = std::get_if<MixDesc>(&m.data))
        for (const std::string& side : {mix->a, mix->b}) grew |= wanted.insert(side).second;
    }
  }
  std::vector<MaterialDesc> out;
  for (const MaterialDesc& m : doc.materials)
    if (wanted.count(m.name)) out.push_back(m);
  return out;
}

}  // namespace

SceneDesc material_preview_scene(const SceneDesc& doc, const std::string& material, int size, int spp) {
  SceneDesc d;
  d.base_dir = doc.base_dir;
  d.render.width = d.render.height = size;
  d.render.spp = spp;
  d.render.max_depth = 8;
  d.render.clamp = 8.f;  // a swatch converges fast rather than exactly
  d.camera.look_from = Point3(0.f, 1.1f, 3.4f);
  d.camera.look_at = Point3(0.f, 0.55f, 0.f);
  d.camera.vfov = 30.f;
  d.environment = GradientEnvironmentDesc{Color(0.45f, 0.55f, 0.75f), Color(0.8f), Color(0.25f)};
  d.materials = with_dependencies(doc, material);
  const std::string floor_name = "preview floor";
  d.materials.push_back({floor_name, DiffuseDesc{CheckerTextureDesc{Color(0.55f), Color(0.2f), 8.f}}, {}});
  ObjectDesc ball;
  ball.name = "preview ball";
  ball.material = material;
  ball.shape = SphereDesc{Point3(0.f, 0.6f, 0.f), 0.6f};
  ObjectDesc floor;
  floor.name = "preview floor";
  floor.material = floor_name;
  floor.shape = QuadDesc{Point3(-3.f, 0.f, -3.f), Vec3(0.f, 0.f, 6.f), Vec3(6.f, 0.f, 0.f)};
  d.objects = {ball, floor};
  d.lights = {{"key", DirectionalLightDesc{Vec3(-0.6f, -1.f, -0.5f), Color(1.f, 0.97f, 0.92f), 2.5f}},
              {"fill", PointLightDesc{Point3(2.5f, 1.5f, 2.5f), Color(0.8f, 0.85f, 1.f), 4.f}}};
  // The document's outlines, so a material's line overrides show on its swatch.
  d.outlines = doc.outlines;
  return d;
}

}  // namespace inkray
