#include "ui/widgets/image_view.h"

#include "core/image/image_io.h"
#include "core/render/display_encode.h"
#include "ui/widgets/gl_texture.h"

#include <GL/gl.h>
#include <fcntl.h>
#include <imgui.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace inkray {
namespace {

namespace fs = std::filesystem;

constexpr float kMinZoom = 1.f / 64.f, kMaxZoom = 64.f;

bool read_written(const fs::path& file, RgbImage* image, std::string* error) {
  switch (image_format_of(file)) {
    case ImageFormat::png:
      return read_image(file, true, image, error);
    case ImageFormat::pfm:
      return read_pfm(file, image, error);
    case ImageFormat::exr:
      return read_exr(file, image, error);
    case ImageFormat::unknown:
      break;
  }
  *error = file.string() + ": not an image an export writes (.png, .exr or .pfm)";
  return false;
}

// "image" for the export's image, else the AOV's name from "<stem>_<aov><ext>".
std::string file_label(const std::vector<fs::path>& files, size_t i) {
  if (i == 0) return "image";
  const std::string stem = files[i].stem().string(), image_stem = files[0].stem().string();
  return stem.size() > image_stem.size() + 1 ? stem.substr(image_stem.size() + 1) : stem;
}

}  // namespace

ImageView::~ImageView() {
  if (texture_) glDeleteTextures(1, &texture_);
  if (reveal_pid_ > 0) waitpid(reveal_pid_, nullptr, WNOHANG);
}

void ImageView::open(std::vector<fs::path> files) {
  files_ = std::move(files);
  open_ = focus_pending_ = !files_.empty();
  reveal_message_.clear();
  if (open_) show(0);
  fit_pending_ = true;
}

void ImageView::show(size_t file) {
  current_ = file;
  read_error_.clear();
  RgbImage image;
  if (!read_written(files_[file], &image, &read_error_)) image = {};
  image_ = std::move(image);
  upload();
}

void ImageView::upload() {
  if (image_.width == 0) return;
  if (!texture_) texture_ = make_image_texture(Magnify::pixels);  // at 1:1 and beyond, pixels are inspected
  const std::vector<uint8_t> rgba =
      encode_display(image_, DisplayEncoding{exposure_, ViewTransform::standard});
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image_.width, image_.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               rgba.data());
}

void ImageView::set_zoom(float zoom, float about_x, float about_y) {
  zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
  offset_x_ = about_x - (about_x - offset_x_) * zoom / zoom_;
  offset_y_ = about_y - (about_y - offset_y_) * zoom / zoom_;
  zoom_ = zoom;
}

void ImageView::draw() {
  if (!open_) return;
  poll_reveal();
  if (focus_pending_) ImGui::SetNextWindowFocus(), focus_pending_ = false;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(
      ImVec2(std::min(840.f, viewport->WorkSize.x * 0.9f), std::min(620.f, viewport->WorkSize.y * 0.9f)),
      ImGuiCond_FirstUseEver);
  const std::string title = "Image: " + files_[0].filename().string() + "###image_view";
  if (ImGui::Begin(title.c_str(), &open_)) {
    toolbar();
    canvas();
  }
  ImGui::End();
}

void ImageView::toolbar() {
  if (ImGui::Button("Fit")) fit_pending_ = true;
  ImGui::SameLine();
  if (ImGui::Button("1:1")) set_zoom(1.f, canvas_w_ * 0.5f, canvas_h_ * 0.5f);
  ImGui::SameLine();
  ImGui::Text("%.0f%%", double(zoom_) * 100.0);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.f);
  if (ImGui::SliderFloat("exposure", &exposure_, -8.f, 8.f, "%+.1f stops")) upload();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.f);
  if (ImGui::BeginCombo("AOV", file_label(files_, current_).c_str())) {
    for (size_t i = 0; i < files_.size(); ++i)
      if (ImGui::Selectable(file_label(files_, i).c_str(), i == current_) && i != current_) show(i);
    ImGui::EndCombo();
  }
  const std::string path = files_[current_].string();
  if (ImGui::Button("Reveal folder")) reveal_folder();
  ImGui::SameLine();
  if (ImGui::Button("Copy path")) ImGui::SetClipboardText(path.c_str());
  ImGui::SameLine();
  ImGui::TextUnformatted(path.c_str());
  if (image_.width > 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("%d x %d", image_.width, image_.height);
  }
  const ImVec4 red(1.f, 0.4f, 0.35f, 1.f);
  if (!reveal_message_.empty()) ImGui::TextColored(red, "%s", reveal_message_.c_str());
  if (!read_error_.empty()) ImGui::TextColored(red, "%s", read_error_.c_str());
}

void ImageView::canvas() {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  canvas_w_ = std::max(avail.x, 32.f);
  canvas_h_ = std::max(avail.y, 32.f);
  ImGui::InvisibleButton("image_canvas", ImVec2(canvas_w_, canvas_h_),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + canvas_w_, origin.y + canvas_h_), IM_COL32(30, 30, 30, 255));
  if (image_.width == 0) return;
  const float w = float(image_.width), h = float(image_.height);
  if (fit_pending_) {
    fit_pending_ = false;
    zoom_ = std::clamp(std::min(canvas_w_ / w, canvas_h_ / h), kMinZoom, kMaxZoom);
    offset_x_ = (canvas_w_ - w * zoom_) * 0.5f;
    offset_y_ = (canvas_h_ - h * zoom_) * 0.5f;
  }
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.f)
    set_zoom(zoom_ * std::pow(1.25f, io.MouseWheel), io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  if (ImGui::IsItemActive()) {
    offset_x_ += io.MouseDelta.x;
    offset_y_ += io.MouseDelta.y;
  }
  const ImVec2 a(origin.x + offset_x_, origin.y + offset_y_);
  draw->PushClipRect(origin, ImVec2(origin.x + canvas_w_, origin.y + canvas_h_), true);
  draw->AddImage(reinterpret_cast<ImTextureID>(uintptr_t(texture_)), a,
                 ImVec2(a.x + w * zoom_, a.y + h * zoom_));
  draw->PopClipRect();
}

void ImageView::reveal_folder() {
  if (reveal_pid_ > 0) return;  // the last one is still starting
  std::string program = "xdg-open", folder = files_[current_].parent_path().string();
  char* argv[] = {program.data(), folder.data(), nullptr};
  // Its own process group, output discarded: the file manager outlives nothing of ours
  // and a Ctrl+C in the editor's terminal does not reach it.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = -1;
  const int err = posix_spawnp(&pid, program.c_str(), &actions, &attr, argv, environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) {
    reveal_message_ = "Reveal folder: could not run xdg-open (" + std::string(std::strerror(err)) + ")";
    return;
  }
  reveal_pid_ = pid;
  reveal_message_.clear();
}

void ImageView::poll_reveal() {
  if (reveal_pid_ <= 0) return;
  int status = 0;
  if (waitpid(reveal_pid_, &status, WNOHANG) != reveal_pid_) return;
  reveal_pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  reveal_message_ = "Reveal folder: xdg-open " + files_[current_].parent_path().string() + " failed" +
                    (WIFEXITED(status) ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")" : "");
}

}  // namespace inkray
