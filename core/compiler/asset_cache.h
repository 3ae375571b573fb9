// The files a document's compiles read, and what was built from them, kept
// between compiles so an edit reads and builds only what it touched
// (docs/architecture.md, "The asset cache"). One compiler owns one cache (the
// editor's viewport has its own, an export another): there is no process-wide
// state, so a compile is a function of the document and the files it names.
#pragma once

#include "core/document/npr_desc.h"
#include "core/geometry/alpha_mask.h"
#include "core/geometry/obj_loader.h"
#include "core/image/image_header.h"
#include "core/image/rgb_image.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace inkray {

// What identifies a file's contents without reading it: its path, modification
// time and size (one stat). An edited or replaced file gets a new stamp.
std::optional<std::string> file_stamp(const std::filesystem::path& file);

// What the editor draws in place of a file that is missing or cannot be read, in the
// look of a graph that does not compile: a magenta and near-black checker. One
// immutable instance each, so a caller can tell a stand-in from a file it read.
inline const Color kStandInEven{1.f, 0.f, 1.f};
inline const Color kStandInOdd{0.05f, 0.f, 0.05f};
const std::shared_ptr<const RgbImage>& stand_in_image();   // 8 x 8 squares over the uv square
const std::shared_ptr<const AlphaMask>& stand_in_brush();  // opaque: the strokes show where they grow

class AssetCache {
 public:
  // Called with every file the cache is about to read (tests count them).
  std::function<void(const std::filesystem::path&)> on_file_read;

  // While set, image(), image_alpha() and brush() answer a file they cannot read with
  // a stand-in (and still set *error); the editor's compiles set it. Stand-ins are
  // never kept under a file's key, so the file is tried again by the next compile.
  void serve_stand_ins(bool on) { stand_ins_ = on; }
  // The reader's error for a file that is there but could not be read. A failure is
  // kept under the file's stamp like a result (a broken file is read once, not on
  // every compile, and again once it changes); a missing file has no stamp, so
  // nothing is kept for it.
  std::optional<std::string> failure(const std::filesystem::path& file);

  // A decoded image (linear RGB), by stamp and colour encoding.
  std::shared_ptr<const RgbImage> image(const std::filesystem::path& file, bool srgb, std::string* error);
  // An image's alpha channel (empty without one), by stamp.
  std::shared_ptr<const std::vector<float>> image_alpha(const std::filesystem::path& file,
                                                        std::string* error);
  // An image's size from its header (image_header.h), by stamp.
  std::optional<ImageSize> image_size(const std::filesystem::path& file, std::string* error);
  // An OBJ mesh as read, in object space, by stamp.
  std::shared_ptr<const TriangleMeshData> mesh(const std::filesystem::path& file, std::string* error);
  // An emitter's brush (brush.h), by the brush parameters and the image's stamp.
  std::shared_ptr<const AlphaMask> brush(const StrokeEmitterDesc& emitter,
                                         const std::filesystem::path& base_dir, std::string* error);

  // What the compiler built (bottom-level BVHs, placed shapes, stroke sets), under
  // keys it makes from everything that shaped them; null when absent.
  // Finding an entry marks it, and what it was built from (`from`), as used.
  template <class T>
  std::shared_ptr<const T> find(const std::string& key) {
    const std::lock_guard lock(mutex_);
    const auto it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    mark_used(key, it->second);
    return std::static_pointer_cast<const T>(it->second.value);
  }
  template <class T>
  std::shared_ptr<const T> keep(const std::string& key, std::shared_ptr<const T> value,
                                std::vector<std::string> from = {}) {
    const std::lock_guard lock(mutex_);
    Entry& entry = entries_[key] = {value, 0, std::move(from)};
    mark_used(key, entry);
    return value;
  }
  // Forgets an entry that nothing of this compile uses any more (the placement of an
  // object that moved), where no finish_compile() follows to drop it.
  void drop(const std::string& key);
  // Marks entries used (those a reused step of the compile found when it ran).
  void touch(const std::vector<std::string>& keys);
  // While set, the keys of every entry found or kept are appended here, so a step
  // whose result is reused later can touch() what it depends on.
  void record_keys(std::vector<std::string>* keys) {
    const std::lock_guard lock(mutex_);
    recording_ = keys;
  }

  // Marks the start of a compile; finish_compile() then drops what that compile did
  // not use, so the cache holds one document's assets. A cancelled or failed compile
  // does not finish: the last good document's assets stay for the next attempt.
  void begin_compile();
  void finish_compile();

  uint64_t files_read() const;
  size_t entries() const;

 private:
  struct Entry {
    std::shared_ptr<const void> value;
    uint64_t used = 0;              // the compile that last used it
    std::vector<std::string> from;  // entries it was built from, kept while it is
  };
  void note_read(const std::filesystem::path& file);
  // The failure kept for this stamp, if any (sets *error).
  bool failed_before(const std::optional<std::string>& stamp, std::string* error);
  void keep_failure(const std::optional<std::string>& stamp, const std::string& error);
  void mark_used(const std::string& key, Entry& entry);  // under mutex_

  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  uint64_t compile_ = 0;
  uint64_t files_read_ = 0;
  std::vector<std::string>* recording_ = nullptr;
  bool stand_ins_ = false;
};

}  // namespace inkray
