// A small ImGui file dialog: a path field, the directory's listing (folders
// first), and an extension filter. Modal; one open at a time.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

class FileDialog {
 public:
  enum class Mode { open, save };

  // `extensions` like {".json"}; empty shows every file.
  void open(std::string title, Mode mode, std::vector<std::string> extensions,
            const std::filesystem::path& start);
  bool is_open() const { return open_; }
  // Draws the dialog; true on the frame the user confirms, with the chosen file.
  bool draw(std::filesystem::path* chosen);

 private:
  bool matches(const std::filesystem::path& file) const;

  std::string title_;
  Mode mode_ = Mode::open;
  std::vector<std::string> extensions_;
  std::filesystem::path directory_;
  std::string name_;
  bool open_ = false, popup_requested_ = false;
};

}  // namespace inkray
