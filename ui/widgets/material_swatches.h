// Material swatches: each material of the document on a small sphere over a
// checker (core/render/material_preview.h), rendered by a ProgressiveRenderer of
// its own on one thread, so the viewport keeps the other cores. One material is
// rendered at a time: the one asked for most recently first (the node editor's),
// then any other whose description changed. Needs a current GL context.
#pragma once

#include "core/render/progressive_renderer.h"

#include <imgui.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace inkray {

class MaterialSwatches {
 public:
  static constexpr int kSize = 96;  // pixels a side
  static constexpr int kSpp = 32;

  MaterialSwatches();
  ~MaterialSwatches();
  MaterialSwatches(const MaterialSwatches&) = delete;
  MaterialSwatches& operator=(const MaterialSwatches&) = delete;

  // Once per frame: uploads what the renderer has, drops swatches of materials
  // gone from `doc`, and starts the next one that is stale.
  // While `hold`, rendering pauses (the viewport has the cores).
  void update(const SceneDesc& doc, bool hold = false);
  // The swatch of a material, or null before its first image.
  ImTextureID texture(const std::string& material) const;
  // Makes `material` the next one rendered whenever it is stale (the node editor's).
  void want(const std::string& material) { wanted_ = material; }

 private:
  struct Swatch {
    std::string key;  // the preview scene it shows (empty: none yet)
    unsigned texture = 0;
    int width = 0, height = 0;
  };
  void upload(Swatch& swatch, const ViewportSnapshot& snapshot);

  ProgressiveRenderer renderer_{1};
  std::map<std::string, Swatch> swatches_;
  std::string rendering_;      // the material in flight, empty when idle
  std::string rendering_key_;  // and the preview scene it was given
  uint64_t revision_ = 0;
  std::chrono::steady_clock::time_point submitted_at_;
  uint64_t uploaded_generation_ = 0;
  bool held_ = false;
  std::string wanted_;
  std::optional<SceneDesc> searched_doc_;  // the document and wish the last search for stale swatches saw
  std::string searched_wish_;
};

}  // namespace inkray
