// The editor's image viewer for finished exports: the files written, read back from
// disk, in a window with zoom about the cursor (wheel), pan (drag), fit and 1:1,
// exposure, a switch among the image and its AOVs, and the file's path with
// "Reveal folder" and "Copy path". Needs a GL context (it owns a texture).
#pragma once

#include "core/image/rgb_image.h"

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

class ImageView {
 public:
  ImageView() = default;
  ~ImageView();
  ImageView(const ImageView&) = delete;
  ImageView& operator=(const ImageView&) = delete;

  // `files`: the image first, then its AOVs. Shows the image, fitted to the window.
  void open(std::vector<std::filesystem::path> files);
  bool is_open() const { return open_; }
  void draw();

 private:
  void show(size_t file);  // reads files_[file] and uploads it
  void upload();
  void set_zoom(float zoom, float about_x, float about_y);  // keeps the image point under (about_x, about_y)
  void toolbar();
  void canvas();
  void reveal_folder();
  void poll_reveal();

  std::vector<std::filesystem::path> files_;
  size_t current_ = 0;
  RgbImage image_;  // linear, as read
  std::string read_error_;
  float exposure_ = 0.f;  // stops
  // Screen pixels per image pixel, and the image's top-left corner from the canvas's.
  float zoom_ = 1.f;
  float offset_x_ = 0.f, offset_y_ = 0.f;
  float canvas_w_ = 0.f, canvas_h_ = 0.f;  // as last drawn, for 1:1 about its centre
  bool fit_pending_ = false, open_ = false, focus_pending_ = false;
  unsigned texture_ = 0;
  // "Reveal folder": the file manager's launcher, reaped when it exits to report a failure.
  pid_t reveal_pid_ = -1;
  std::string reveal_message_;
};

}  // namespace inkray
