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

const std::shared_ptr<const RgbImage>& stand_in_image() {
  static const std::shared_ptr<const RgbImage> image = [] {
    // 8 texels a square: bilinear filtering softens only the squares' edges.
    constexpr int kSquares = 8, kTexels = 8;
    auto checker = std::make_shared<RgbImage>();
    checker->width = checker->height = kSquares * kTexels;
    checker->pixels.resize(size_t(checker->width) * size_t(checker->height));
    for (int y = 0; y < checker->height; ++y)
      for (int x = 0; x < checker->width; ++x)
        checker->at(x, y) = ((x / kTexels + y / kTexels) & 1) ? kStandInOdd : kStandInEven;
    return std::shared_ptr<const RgbImage>(std::move(checker));
  }();
  return image;
}

const std::shared_ptr<const AlphaMask>& stand_in_brush() {
  static const std::shared_ptr<const AlphaMask> mask = [] {
    auto opaque = std::make_shared<AlphaMask>();
    opaque->width = opaque->height = 1;
    opaque->texels = {255};
    return std::shared_ptr<const AlphaMask>(std::move(opaque));
  }();
  return mask;
}

void AssetCache::note_read(const std::filesystem::path& file) {
  {
    const std::lock_guard lock(mutex_);
    ++files_read_;
  }
  if (on_file_read) on_file_read(file);
}

bool AssetCache::failed_before(const std::optional<std::string>& stamp, std::string* error) {
  if (!stamp) return false;
  const auto found = find<std::string>("failed|" + *stamp);
  if (!found) return false;
  *error = *found;
  return true;
}

void AssetCache::keep_failure(const std::optional<std::string>& stamp, const std::string& error) {
  if (stamp) keep("failed|" + *stamp, std::make_shared<const std::string>(error));
}

std::optional<std::string> AssetCache::failure(const std::filesystem::path& file) {
  std::string error;
  if (!failed_before(file_stamp(file), &error)) return std::nullopt;
  return error;
}

std::shared_ptr<const RgbImage> AssetCache::image(const std::filesystem::path& file, bool srgb,
                                                  std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image|" + (stamp ? *stamp : file.string()) + (srgb ? "|srgb" : "|linear");
  if (stamp)
    if (auto found = find<RgbImage>(key)) return found;
  const auto unreadable = [&]() -> std::shared_ptr<const RgbImage> {
    return stand_ins_ ? stand_in_image() : nullptr;
  };
  if (failed_before(stamp, error)) return unreadable();
  note_read(file);
  RgbImage image;
  if (!read_image(file, srgb, &image, error)) {
    keep_failure(stamp, *error);
    return unreadable();
  }
  auto value = std::make_shared<const RgbImage>(std::move(image));
  return stamp ? keep(key, std::move(value)) : value;
}

std::shared_ptr<const std::vector<float>> AssetCache::image_alpha(const std::filesystem::path& file,
                                                                  std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image alpha|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<std::vector<float>>(key)) return found;
  // A stand-in is opaque: no alpha channel.
  const auto unreadable = [&] { return stand_ins_ ? std::make_shared<const std::vector<float>>() : nullptr; };
  if (failed_before(stamp, error)) return unreadable();
  note_read(file);
  std::vector<float> alpha;
  if (!read_image_alpha(file, &alpha, error)) {
    keep_failure(stamp, *error);
    return unreadable();
  }
  auto value = std::make_shared<const std::vector<float>>(std::move(alpha));
  return stamp ? keep(key, std::move(value)) : value;
}

std::optional<ImageSize> AssetCache::image_size(const std::filesystem::path& file, std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "image size|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<ImageSize>(key)) return *found;
  if (failed_before(stamp, error)) return std::nullopt;
  note_read(file);
  const auto size = read_image_size(file, error);
  if (size && stamp) keep(key, std::make_shared<const ImageSize>(*size));
  if (!size) keep_failure(stamp, *error);
  return size;
}

std::shared_ptr<const TriangleMeshData> AssetCache::mesh(const std::filesystem::path& file,
                                                         std::string* error) {
  const auto stamp = file_stamp(file);
  const std::string key = "mesh|" + (stamp ? *stamp : file.string());
  if (stamp)
    if (auto found = find<TriangleMeshData>(key)) return found;
  if (failed_before(stamp, error)) return nullptr;
  note_read(file);
  auto data = load_obj(file, error);
  if (!data) {
    keep_failure(stamp, *error);
    return nullptr;
  }
  auto value = std::make_shared<const TriangleMeshData>(std::move(*data));
  return stamp ? keep(key, std::move(value)) : value;
}

std::shared_ptr<const AlphaMask> AssetCache::brush(const StrokeEmitterDesc& e,
                                                   const std::filesystem::path& base_dir,
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
  const auto unreadable = [&]() -> std::shared_ptr<const AlphaMask> {
    return stand_ins_ && from_file ? stand_in_brush() : nullptr;
  };
  if (failed_before(stamp, error)) return unreadable();
  if (from_file) note_read(base_dir / e.brush_image);
  auto mask = make_brush_mask(e, base_dir, error);
  if (!mask) {
    keep_failure(stamp, *error);
    return unreadable();
  }
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

void AssetCache::drop(const std::string& key) {
  const std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  if (it != entries_.end() && it->second.used != compile_) entries_.erase(it);
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
