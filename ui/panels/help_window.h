// F1: the shortcut list and where to read more; Help > About: version, licences.
#pragma once

namespace inkray {

class HelpWindow {
 public:
  void show_shortcuts() { shortcuts_open_ = true; }
  void show_about() { about_open_ = true; }
  void draw();

 private:
  bool shortcuts_open_ = false;
  bool about_open_ = false;
};

}  // namespace inkray
