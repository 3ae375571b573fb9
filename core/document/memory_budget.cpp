// The memory estimate: per-item costs times counts. The costs are the extra peak
// resident memory of inkray-render over scenes that scale one item at a time
// (scripts/measure_memory_costs prints them; measured figures in the comments),
// rounded up, so the estimate errs high.
#include "core/document/memory_budget.h"

#include "core/image/image_header.h"
#include "core/document/error_log.h"
#include "core/document/scene_checks.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <system_error>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

// Film buffers and the resolved image: 56 measured without AOVs; every AOV and
// line coverage (the editor's viewport can show them all) add about 100.
constexpr std::uint64_t kFilmBytesPerPixel = 160;
// A shape, its own Embree scene and the instance placing it, its records and cache
// entries (a sphere; boxes and quads are meshes of 12 and 2 triangles).
constexpr std::uint64_t kBytesPerObject = 6144;  // 5924 measured
// A loaded OBJ mesh and its BVH per byte of OBJ text.
constexpr std::uint64_t kBytesPerMeshFileByte = 7;  // 6.72 measured
// A ribbon vertex: attributes, its share of indices, the kept copy and the BVH.
constexpr std::uint64_t kBytesPerStrokeVertex = 200;  // 162 measured
// Linear float RGB and the 8-bit decode it is made from: 14.9 measured.
constexpr std::uint64_t kBytesPerTexel = 16;
// A brush image decoded as RGBA and baked into two 8-bit variants (by construction).
constexpr std::uint64_t kBytesPerBrushTexel = 6;
// An animation key of three values: read from JSON, and held in the document and in
// the copies of it at the frame and the shutter's ends that the compiler keeps.
constexpr std::uint64_t kBytesPerKey = 768;  // 695 measured

struct Estimator {
  const SceneDesc& scene;
  const ImageSizeReader& read_size;
  MemoryEstimate estimate;
  std::set<fs::path> images_seen;  // a texture used by several materials is decoded once

  void add(std::string what, std::uint64_t bytes) {
    if (bytes == 0) return;
    estimate.total += bytes;
    estimate.items.push_back({std::move(what), bytes});
  }

  void image(const std::string& at, const std::string& path, std::uint64_t bytes_per_texel) {
    if (path.empty()) return;
    const fs::path file = scene.base_dir / path;
    if (!images_seen.insert(file.lexically_normal()).second) return;
    std::string error;
    const auto size = read_size(file, &error);
    if (!size) return;
    estimate.texels += size->texels();
    add(at, std::uint64_t(size->texels()) * bytes_per_texel);
  }
};

}  // namespace

MemoryEstimate estimate_memory(const SceneDesc& scene, const ImageSizeReader& read_size) {
  Estimator e{scene, read_size, {}, {}};
  e.add("film", std::uint64_t(scene.render.width) * std::uint64_t(scene.render.height) * kFilmBytesPerPixel);
  for (const AssetRef& asset : collect_assets(scene)) {
    if (asset.kind == AssetKind::image) e.image(asset.at, asset.written, kBytesPerTexel);
    if (asset.kind == AssetKind::brush) e.image(asset.at, asset.written, kBytesPerBrushTexel);
  }
  std::uint64_t simple_objects = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& o = scene.objects[i];
    if (!o.visible) continue;
    ++simple_objects;
    if (const auto* mesh = std::get_if<MeshDesc>(&o.shape)) {
      std::error_code ec;
      const std::uintmax_t size = fs::file_size(scene.base_dir / mesh->path, ec);
      if (!ec) e.add(element_path("objects", i) + " (mesh " + mesh->path + ")", size * kBytesPerMeshFileByte);
    }
  }
  e.add("objects (" + std::to_string(simple_objects) + ")", simple_objects * kBytesPerObject);
  for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
    const StrokeEmitterDesc& s = scene.strokes[i];
    const std::string at = element_path("strokes", i);
    e.add(at + " (" + std::to_string(s.count) + " strokes)",
          std::uint64_t(stroke_vertex_count(s)) * kBytesPerStrokeVertex);
  }
  std::uint64_t keys = 0;
  for (const TrackDesc& track : scene.animation) keys += track.keys.size();
  e.add("animation (" + std::to_string(keys) + " keys)", keys * kBytesPerKey);
  std::sort(e.estimate.items.begin(), e.estimate.items.end(),
            [](const MemoryItem& a, const MemoryItem& b) { return a.bytes > b.bytes; });
  return e.estimate;
}

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t(8) << 30;  // unknown: assume a small laptop
  return std::uint64_t(pages) * std::uint64_t(page);
}

std::uint64_t default_memory_limit() { return physical_memory_bytes() / 2; }

std::string format_bytes(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (std::uint64_t(1) << 30)) {
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1 << 30));
  } else {
    std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(1 << 20));
  }
  return text;
}

void check_memory_budget(const SceneDesc& scene, std::uint64_t limit, std::vector<std::string>& errors,
                         const ImageSizeReader& read_size) {
  if (limit == 0) limit = default_memory_limit();
  const MemoryEstimate estimate = estimate_memory(scene, read_size);
  if (estimate.texels > kMaxSceneTexels) {
    errors.push_back("the scene's images have " + std::to_string(estimate.texels) +
                     " texels together; a scene may decode at most " + std::to_string(kMaxSceneTexels) +
                     " (four 8192 x 8192 images)");
  }
  if (estimate.total <= limit) return;
  std::string largest;
  for (std::size_t i = 0; i < estimate.items.size() && i < 3; ++i)
    largest += (i ? ", " : "") + estimate.items[i].what + ": " + format_bytes(estimate.items[i].bytes);
  errors.push_back("the scene would need about " + format_bytes(estimate.total) + " of memory (" + largest +
                   "), more than the limit of " + format_bytes(limit) +
                   " (half the machine's memory unless set with --memory-limit)");
}

}  // namespace inkray
