#include "ui/widgets/material_swatches.h"

#include "core/document/json_io.h"
#include "core/render/material_preview.h"
#include "ui/widgets/gl_texture.h"

#include <GL/gl.h>
#include <nlohmann/json.hpp>

#include <set>

namespace inkray {
namespace {

// What the swatch depends on: the preview scene, without graphs' canvas layout.
std::string preview_key(const SceneDesc& preview) {
  SceneDesc keyed = preview;
  for (MaterialDesc& m : keyed.materials)
    if (auto* g = std::get_if<GraphDesc>(&m.data)) g->editor = {};
  return scene_to_string(keyed);
}

}  // namespace

MaterialSwatches::MaterialSwatches() { renderer_.set_limits({kSpp, 0.0, 0.0}); }

MaterialSwatches::~MaterialSwatches() {
  for (auto& [name, swatch] : swatches_)
    if (swatch.texture) glDeleteTextures(1, &swatch.texture);
}

void MaterialSwatches::upload(Swatch& swatch, const ViewportSnapshot& s) {
  if (!swatch.texture) swatch.texture = make_image_texture();
  glBindTexture(GL_TEXTURE_2D, swatch.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, s.width, s.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, s.rgba.data());
  swatch.width = s.width;
  swatch.height = s.height;
}

void MaterialSwatches::update(const SceneDesc& doc, bool hold) {
  if (hold != held_) renderer_.set_paused(held_ = hold);
  std::set<std::string> names;
  for (const MaterialDesc& m : doc.materials) names.insert(m.name);
  for (auto it = swatches_.begin(); it != swatches_.end();) {
    if (names.count(it->first)) {
      ++it;
      continue;
    }
    if (it->second.texture) glDeleteTextures(1, &it->second.texture);
    it = swatches_.erase(it);
  }

  // What the renderer has for the material in flight.
  if (!rendering_.empty()) {
    const auto snapshot = renderer_.latest();
    if (snapshot && snapshot->revision == revision_ && renderer_.generation() != uploaded_generation_) {
      uploaded_generation_ = renderer_.generation();
      if (names.count(rendering_)) {
        upload(swatches_[rendering_], *snapshot);
        if (snapshot->finished) {
          swatches_[rendering_].key = rendering_key_;
          rendering_.clear();
          searched_doc_.reset();  // look for the next stale one
        }
      }
    }
    // A material that cannot compile never shows an image (the viewport's log says why;
    // a broken graph compiles to its stand-in and does). Move on after a while.
    renderer_.take_messages();
    renderer_.take_warnings();
    const bool gave_up = std::chrono::steady_clock::now() - submitted_at_ > std::chrono::seconds(10);
    if (!rendering_.empty() && gave_up && (!snapshot || snapshot->revision != revision_)) {
      if (names.count(rendering_)) swatches_[rendering_].key = rendering_key_;
      rendering_.clear();
      searched_doc_.reset();
    }
  }
  // Nothing to look for while the document and the wish are those of the last search.
  if (rendering_.empty() && searched_doc_ && *searched_doc_ == doc && searched_wish_ == wanted_) return;
  searched_doc_ = doc;
  searched_wish_ = wanted_;

  // The next stale swatch: the wanted one first, and an edit to the one in flight restarts it.
  std::string next;
  std::string next_key;
  const auto stale = [&](const std::string& name, std::string* key) {
    *key = preview_key(material_preview_scene(doc, name, kSize, kSpp));
    const auto it = swatches_.find(name);
    return it == swatches_.end() || it->second.key != *key;
  };
  if (!rendering_.empty()) {
    std::string key;
    if (names.count(rendering_) && stale(rendering_, &key) && key == rendering_key_)
      return;  // still refining
  }
  if (!wanted_.empty() && names.count(wanted_) && stale(wanted_, &next_key)) next = wanted_;
  for (const MaterialDesc& m : doc.materials) {
    if (!next.empty()) break;
    if (stale(m.name, &next_key)) next = m.name;
  }
  if (next.empty()) {
    rendering_.clear();
    return;
  }
  rendering_ = next;
  rendering_key_ = next_key;
  revision_ = renderer_.submit(material_preview_scene(doc, next, kSize, kSpp));
  submitted_at_ = std::chrono::steady_clock::now();
}

ImTextureID MaterialSwatches::texture(const std::string& material) const {
  const auto it = swatches_.find(material);
  if (it == swatches_.end() || !it->second.texture) return ImTextureID{};
  return reinterpret_cast<ImTextureID>(uintptr_t(it->second.texture));
}

}  // namespace inkray
