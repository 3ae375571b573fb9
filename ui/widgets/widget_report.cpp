#include "ui/widgets/widget_report.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <map>

namespace inkray::widget_report {
namespace {

struct Entry {
  ImVec2 min, max, visible_min, visible_max;
};

bool g_enabled = false;
std::map<std::string, Entry, std::less<>> g_entries;

}  // namespace

void enable(bool on) { g_enabled = on; }
bool enabled() { return g_enabled; }
void begin_frame() { g_entries.clear(); }

void item(std::string_view name) {
  if (!g_enabled) return;
  const ImGuiWindow* window = ImGui::GetCurrentWindowRead();
  const ImRect visible = window->InnerClipRect;
  g_entries[std::string(name)] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), visible.Min, visible.Max};
}

std::string text() {
  std::string out;
  char line[512];
  for (const auto& [name, e] : g_entries) {
    std::snprintf(line, sizeof line, "%s %.1f %.1f %.1f %.1f %.1f %.1f %.1f %.1f\n", name.c_str(), e.min.x,
                  e.min.y, e.max.x, e.max.y, e.visible_min.x, e.visible_min.y, e.visible_max.x,
                  e.visible_max.y);
    out += line;
  }
  return out;
}

}  // namespace inkray::widget_report
