// The recently opened documents, newest first, kept in a text file (one path a line).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

class RecentFiles {
 public:
  static constexpr size_t kMaxEntries = 10;

  explicit RecentFiles(std::filesystem::path store) : store_(std::move(store)) {}

  void load();
  // Moves `file` to the front and writes the list back.
  void add(const std::filesystem::path& file);
  void remove(const std::filesystem::path& file);
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  void save() const;

  std::filesystem::path store_;
  std::vector<std::filesystem::path> files_;
};

}  // namespace inkray
