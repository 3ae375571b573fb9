#include "ui/panels/log_panel.h"

#include <imgui.h>

namespace inkray {

void draw_log_panel(Log& log) {
  if (ImGui::SmallButton("Clear")) log.clear();
  ImGui::Separator();
  ImGui::BeginChild("log_lines", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  for (const LogLine& line : log.lines()) {
    const ImVec4 colour = line.level == LogLevel::error     ? ImVec4(1.f, 0.45f, 0.4f, 1.f)
                          : line.level == LogLevel::warning ? ImVec4(1.f, 0.8f, 0.35f, 1.f)
                                                            : ImVec4(0.85f, 0.85f, 0.85f, 1.f);
    ImGui::TextDisabled("%8.2f", line.seconds);
    ImGui::SameLine();
    ImGui::TextColored(colour, "%s", line.text.c_str());
  }
  // Follow new lines unless the user scrolled up to read.
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 4.f) ImGui::SetScrollHereY(1.f);
  ImGui::EndChild();
}

}  // namespace inkray
