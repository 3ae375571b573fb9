// Scene file input and output: reading files without throwing, and saving through
// core/io's atomic replacement so an interrupted save never destroys the previous scene.
#include "core/document/json_io.h"

#include "core/io/atomic_file.h"
#include "core/document/asset_paths.h"
#include "core/document/error_log.h"
#include "core/document/json_read.h"
#include "core/document/json_syntax.h"
#include "core/document/json_write.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <new>
#include <system_error>

namespace inkray {
namespace fs = std::filesystem;

namespace {

std::string errno_text(int error_number) { return std::generic_category().message(error_number); }

// Reads a whole file; false with a reason (without the file name) on failure.
bool read_text_file(const fs::path& file, std::string& text, std::string& reason) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) {
    reason = "cannot open the scene file: no such file";
    return false;
  }
  if (!fs::is_regular_file(status)) {
    reason = "cannot open the scene file: not a regular file";
    return false;
  }
  const std::uintmax_t size = fs::file_size(file, ec);
  if (!ec && size > kMaxSceneFileBytes) {
    reason = "the file is " + std::to_string(size) + " bytes; a scene file may be at most " +
             std::to_string(kMaxSceneFileBytes >> 20) + " MiB";
    return false;
  }
  std::FILE* stream = std::fopen(file.c_str(), "rb");
  if (!stream) {
    reason = "cannot open the scene file: " + errno_text(errno);
    return false;
  }
  text.clear();
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, stream)) > 0) {
    text.append(buffer, n);
    if (text.size() > kMaxSceneFileBytes) break;  // the file grew since we asked its size
  }
  const bool failed = std::ferror(stream) != 0;
  const int read_errno = errno;
  std::fclose(stream);
  if (failed) {
    reason = "cannot read the scene file: " + errno_text(read_errno);
    return false;
  }
  if (text.size() > kMaxSceneFileBytes) {
    reason = "the file is larger than " + std::to_string(kMaxSceneFileBytes >> 20) + " MiB";
    return false;
  }
  return true;
}

}  // namespace

SceneLoadResult parse_scene(std::string_view json_text, const fs::path& base_dir, std::string_view file_label,
                            ReadFor purpose, const Cancel& cancel) {
  SceneLoadResult result;
  ErrorLog log(file_label, purpose);
  try {
    if (json_text.size() > kMaxSceneFileBytes) {
      log.add("", "the text is " + std::to_string(json_text.size()) + " bytes; a scene may be at most " +
                      std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
    } else if (std::optional<nlohmann::json> doc = parse_json_document(json_text, log, cancel)) {
      SceneDesc scene;
      read_scene_document(*doc, base_dir, scene, log, cancel);
      scene.base_dir = base_dir;
      if (log.empty()) result.scene = std::move(scene);
    }
  } catch (const std::bad_alloc&) {
    log.add("", "out of memory while reading the scene");
  } catch (const std::exception& e) {
    log.add("", std::string("internal error while reading the scene: ") + e.what());
  } catch (...) {
    log.add("", "internal error while reading the scene");
  }
  result.cancelled = !log.empty() && cancel.requested();
  result.errors = log.take();
  result.warnings = log.take_warnings();
  if (!result.errors.empty()) result.scene.reset();
  return result;
}

SceneLoadResult load_scene(const fs::path& file, ReadFor purpose, const Cancel& cancel) {
  const std::string label = file.string();
  try {
    std::string text, reason;
    if (!read_text_file(file, text, reason)) return {std::nullopt, {label + ": " + reason}, {}, false};
    std::error_code ec;
    fs::path dir = fs::absolute(file, ec).parent_path();
    if (ec) dir = file.parent_path();
    return parse_scene(text, dir.lexically_normal(), label, purpose, cancel);
  } catch (const std::exception& e) {
    return {std::nullopt, {label + ": cannot read the scene file: " + e.what()}, {}, false};
  } catch (...) {
    return {std::nullopt, {label + ": cannot read the scene file"}, {}, false};
  }
}

nlohmann::json scene_to_json(const SceneDesc& scene) { return nlohmann::json(write_scene_document(scene)); }

std::string scene_to_string(const SceneDesc& scene) { return format_scene_json(write_scene_document(scene)); }

bool save_scene(const SceneDesc& scene, const fs::path& file, std::string* error) {
  std::string text;
  try {
    text = scene_to_string(scene);
  } catch (const std::exception& e) {
    if (error) *error = "cannot save " + file.string() + ": " + e.what();
    return false;
  }
  // A save killed mid-write left its temporary: staging the file removes it.
  return write_file_atomically(file, text, error);
}

bool save_scene_as(const SceneDesc& scene, const fs::path& file, std::string* error) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(file, ec);
  if (ec) {
    if (error) *error = "cannot save " + file.string() + ": " + ec.message();
    return false;
  }
  const fs::path from = scene.base_dir.empty() ? fs::current_path(ec) : scene.base_dir;
  SceneDesc written = scene;
  rebase_asset_paths(written, from, absolute.parent_path());
  return save_scene(written, absolute, error);
}

}  // namespace inkray
