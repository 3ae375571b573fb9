// What a scene will take in memory, estimated from the document, image headers and
// file sizes before anything large is allocated, and checked against a budget (by
// default half the machine's memory; inkray-render --memory-limit sets it). The
// per-item costs are measured; docs/architecture.md says how.
#pragma once

#include "core/document/desc.h"
#include "core/image/image_header.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace inkray {

// All images a scene decodes together (textures, toon ramps, brush images): four
// of the largest single image, 3 GiB as linear float RGB.
inline constexpr long long kMaxSceneTexels = 4LL * 8192LL * 8192LL;

struct MemoryItem {
  std::string what;  // a JSON path or "film"
  std::uint64_t bytes = 0;
};

struct MemoryEstimate {
  std::uint64_t total = 0;
  long long texels = 0;           // decoded image texels, all images together
  std::vector<MemoryItem> items;  // largest first
};

// How image sizes are found: read_image_size, or a compiler's cache of them.
using ImageSizeReader = std::function<std::optional<ImageSize>(const std::filesystem::path&, std::string*)>;

// Reads image headers and mesh file sizes only; an unreadable asset counts zero
// (loading it reports the problem).
MemoryEstimate estimate_memory(const SceneDesc& scene, const ImageSizeReader& read_size = read_image_size);

std::uint64_t physical_memory_bytes();
std::uint64_t default_memory_limit();  // half of physical memory

// "12.3 GiB", "850 MiB".
std::string format_bytes(std::uint64_t bytes);

// Appends an error naming the largest items when the estimate exceeds `limit`
// bytes (0: default_memory_limit()) or the images exceed kMaxSceneTexels.
void check_memory_budget(const SceneDesc& scene, std::uint64_t limit, std::vector<std::string>& errors,
                         const ImageSizeReader& read_size = read_image_size);

}  // namespace inkray
