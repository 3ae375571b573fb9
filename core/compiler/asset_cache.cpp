#include "core/compiler/asset_cache.h"

#include "core/document/param_key.h"
#include "core/image/image_io.h"
#include "core/npr/strokes/brush.h"

#include <chrono>

namespace inkray {

std::optional<std::string> file_stamp(const std::filesystem::path& file) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::is_regular_file(status)) return std::nullopt;
  const auto time = std::filesystem::last_write_time(file, ec);
  if (ec) return std::nullopt;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return std::nullopt;
  return std::filesystem::absolute(file).lexically_normal().string() + "|" +
         std::to_string(time.time_since_epoch().count()) + "|" + std::to_string(size);
}

void AssetCache::note_read(const std::filesystem::path& file) {
  {
    const std::lock_guard lock(mutex_);
    ++files_read_;
  }
  if (on_file_read) on_file_read(file);
}

std::shared_ptr<const RgbImage> AssetCache::image(const std::filesystem::path& file, bool srgb, std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image|" + (stamp ? *stamp : file.string()) + (srgb ? "|srgb" : "|linear");
  if (stamp)
    if (auto found = find<RgbImage>(key)) return found;
  note_read(file);
  RgbImage image;
  if (!read_image(file, srgb, &image, error)) return nullptr;
  auto value = std::make_shared<const RgbImage>(std::move(image));
  return stamp ? keep(key, std::move(value)) : value;
}

std::shared_ptr<const std::vector<float>> AssetCache::image_alpha(const std::filesystem::path& file,
                                                                std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image alpha|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<std::vector<float>>(key)) return found;
  note_read(file);
  std::vector<float> alpha;
  if (!read_image_alpha(file, &alpha, error)) return nullptr;
  auto value = std::make_shared<const std::vector<float>>(std::move(alpha));
  return stamp ? keep(key, std::move(value)) : value;
}

std::optional<ImageSize> AssetCache::image_size(const std::filesystem::path& file, std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image size|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<ImageSize>(key)) return *found;
  note_read(file);
  const auto size = read_image_size(file, error);
  if (size && stamp) keep(key, std::make_shared<const ImageSize>(*size));
  return size;
}

std::shared_ptr<const TriangleMeshData> AssetCache::mesh(const std::filesystem::path& file, std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "mesh|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<TriangleMeshData>(key)) return found;
  note_read(file);
  auto data = load_obj(file, error);
  if (!data) return nullptr;
  auto value = std::make_shared<const TriangleMeshData>(std::move(*data));
  return stamp ? keep(key, std::move(value)) : value;
}

std::shared_ptr<const AlphaMask> AssetCache::brush(const StrokeEmitterDesc& e, const std::filesystem::path& base_dir,
                                                   std::string* error) {
  std::string key = "brush|";
  append_key(key, e.brush);
  append_key(key, e.bristles);
  append_key(key, e.pressure);
  const bool from_file = e.brush == BrushKind::image && !e.brush_image.empty();
  std::optional<std::string> stamp;
  if (from_file) {
    stamp = file_stamp(base_dir / e.brush_image);
    key += "|" + (stamp ? *stamp : (base_dir / e.brush_image).string());
  }
  if (!from_file || stamp)
    if (auto found = find<AlphaMask>(key)) return found;
  if (from_file) note_read(base_dir / e.brush_image);
  auto mask = make_brush_mask(e, base_dir, error);
  if (!mask) return nullptr;
  std::shared_ptr<const AlphaMask> value = std::move(mask);
  return !from_file || stamp ? keep(key, std::move(value)) : value;
}

void AssetCache::mark_used(const std::string& key, Entry& entry) {
  if (recording_) recording_->push_back(key);
  if (entry.used == compile_) return;
  entry.used = compile_;
  for (const std::string& source : entry.from)
    if (const auto it = entries_.find(source); it != entries_.end()) mark_used(source, it->second);
}

void AssetCache::touch(const std::vector<std::string>& keys) {
  const std::lock_guard lock(mutex_);
  for (const std::string& key : keys)
    if (const auto it = entries_.find(key); it != entries_.end()) mark_used(key, it->second);
}

void AssetCache::begin_compile() {
  const std::lock_guard lock(mutex_);
  ++compile_;
}

void AssetCache::finish_compile() {
  const std::lock_guard lock(mutex_);
  std::erase_if(entries_, [&](const auto& entry) { return entry.second.used != compile_; });
}

uint64_t AssetCache::files_read() const {
  const std::lock_guard lock(mutex_);
  return files_read_;
}

size_t AssetCache::entries() const {
  const std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace inkray
