// Scene file input and output: reading files without throwing, and saving through a
// temporary file and rename so an interrupted save never destroys the previous scene.
#include "core/scene/json_io.h"

#include "core/scene/asset_paths.h"
#include "core/scene/error_log.h"
#include "core/scene/json_read.h"
#include "core/scene/json_syntax.h"
#include "core/scene/json_write.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <new>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

std::string temporary_suffix() {
  static std::atomic<unsigned> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  std::size_t h = std::hash<long long>{}(static_cast<long long>(now));
  h ^= std::hash<unsigned>{}(counter.fetch_add(1) + 0x9e3779b9u * static_cast<unsigned>(::getpid())) +
       0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string suffix(6, '0');
  for (char& c : suffix) {
    c = kHex[h & 15];
    h >>= 4;
  }
  return suffix;
}

bool write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Makes the rename itself durable; failure only weakens durability, so it is ignored.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

SceneLoadResult parse_scene(std::string_view json_text, const fs::path& base_dir,
                            std::string_view file_label) {
  SceneLoadResult result;
  ErrorLog log(file_label);
  try {
    if (json_text.size() > kMaxSceneFileBytes) {
      log.add("", "the text is " + std::to_string(json_text.size()) + " bytes; a scene may be at most " +
                      std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
    } else if (std::optional<nlohmann::json> doc = parse_json_document(json_text, log)) {
      SceneDesc scene;
      read_scene_document(*doc, base_dir, scene, log);
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
  result.errors = log.take();
  if (!result.errors.empty()) result.scene.reset();
  return result;
}

SceneLoadResult load_scene(const fs::path& file) {
  const std::string label = file.string();
  try {
    std::string text, reason;
    if (!read_text_file(file, text, reason)) return {std::nullopt, {label + ": " + reason}};
    std::error_code ec;
    fs::path dir = fs::absolute(file, ec).parent_path();
    if (ec) dir = file.parent_path();
    return parse_scene(text, dir.lexically_normal(), label);
  } catch (const std::exception& e) {
    return {std::nullopt, {label + ": cannot read the scene file: " + e.what()}};
  } catch (...) {
    return {std::nullopt, {label + ": cannot read the scene file"}};
  }
}

nlohmann::json scene_to_json(const SceneDesc& scene) { return nlohmann::json(write_scene_document(scene)); }

std::string scene_to_string(const SceneDesc& scene) { return format_scene_json(write_scene_document(scene)); }

bool save_scene(const SceneDesc& scene, const fs::path& file, std::string* error) {
  const auto fail = [&](const std::string& reason) {
    if (error) *error = "cannot save " + file.string() + ": " + reason;
    return false;
  };
  std::string text;
  fs::path target = file;
  try {
    text = scene_to_string(scene);
    // Saving through a symlink replaces the file it points to, not the link.
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(file, ec))) {
      const fs::path resolved = fs::canonical(file, ec);
      if (!ec) target = resolved;
    }
  } catch (const std::exception& e) {
    return fail(e.what());
  }

  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 64 && fd < 0; ++attempt) {
    temporary = target.string() + ".tmp-" + temporary_suffix();
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) return fail("cannot create " + temporary + ": " + errno_text(errno));
  }
  if (fd < 0) return fail("cannot create a temporary file next to it");

  // Keep the permissions of the file being replaced.
  struct stat existing;
  if (::stat(target.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
    ::fchmod(fd, existing.st_mode & 07777);
  }

  const auto abandon = [&](const std::string& what) {
    const std::string reason = what + ": " + errno_text(errno);
    if (fd >= 0) ::close(fd);
    ::unlink(temporary.c_str());
    return fail(reason);
  };
  if (!write_all(fd, text)) return abandon("cannot write " + temporary);
  if (::fsync(fd) != 0) return abandon("cannot flush " + temporary);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) return abandon("cannot close " + temporary);
  if (::rename(temporary.c_str(), target.c_str()) != 0) return abandon("cannot rename " + temporary);
  const fs::path dir = target.parent_path();
  sync_directory(dir.empty() ? fs::path(".") : dir);
  return true;
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
