#include "ui/model/recent_files.h"

#include "core/io/atomic_file.h"

#include <algorithm>
#include <fstream>

namespace inkray {

void RecentFiles::load() {
  files_.clear();
  std::ifstream in(store_);
  std::string line;
  while (std::getline(in, line) && files_.size() < kMaxEntries) {
    if (!line.empty()) files_.emplace_back(line);
  }
}

void RecentFiles::add(const std::filesystem::path& file) {
  const std::filesystem::path absolute = std::filesystem::absolute(file);
  std::erase(files_, absolute);
  files_.insert(files_.begin(), absolute);
  if (files_.size() > kMaxEntries) files_.resize(kMaxEntries);
  save();
}

void RecentFiles::remove(const std::filesystem::path& file) {
  std::erase(files_, file);
  save();
}

void RecentFiles::save() const {
  std::error_code ec;
  std::filesystem::create_directories(store_.parent_path(), ec);
  // Replaced atomically (core/io), so a crash mid-save keeps the previous list.
  std::string text;
  for (const auto& f : files_) text += f.string() + '\n';
  write_file_atomically(store_, text, nullptr);
}

}  // namespace inkray
