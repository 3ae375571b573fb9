#include "ui/widgets/fonts.h"

#include <imgui.h>

#include <cmath>
#include <cstdlib>

namespace inkray {
namespace {

constexpr float kBaseFontPixels = 15.f;

// Latin and Latin-1, general punctuation (dashes, ellipsis), arrows, maths operators and
// geometric shapes: what labels, units and node titles use.
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x2000, 0x206F, 0x2190, 0x21FF,
                                    0x2200, 0x22FF, 0x25A0, 0x25FF, 0};

}  // namespace

float ui_scale_of_font() { return ImGui::GetFontSize() / kBaseFontPixels; }

std::filesystem::path resource_dir() {
  if (const char* dir = std::getenv("INKRAY_RESOURCE_DIR"); dir && *dir) return dir;
  return INKRAY_RESOURCE_DIR;
}

void set_ui_scale(float scale, std::string* warning) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const std::filesystem::path font = resource_dir() / "fonts" / "DejaVuSans.ttf";
  ImFontConfig config;
  config.OversampleH = 2;  // sharper small text at a modest atlas size
  ImFont* loaded = nullptr;
  std::error_code ec;
  if (std::filesystem::is_regular_file(font, ec)) {
    loaded = io.Fonts->AddFontFromFileTTF(font.string().c_str(), std::round(kBaseFontPixels * scale), &config,
                                          kGlyphRanges);
  }
  if (!loaded) {
    if (warning) *warning = "cannot read the UI font " + font.string() + "; using the built-in font";
    ImFontConfig fallback;
    fallback.SizePixels = std::round(13.f * scale);
    io.Fonts->AddFontDefault(&fallback);
  }
  io.Fonts->Build();

  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 0.f;
  style.FrameRounding = 3.f;
  style.WindowBorderSize = 1.f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace inkray
