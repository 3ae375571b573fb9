#include "ui/widgets/toolbar_flow.h"

#include <imgui.h>

namespace inkray {

void ToolbarFlow::next(float width) {
  if (started_) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
  }
  started_ = true;
}

float text_width(const char* label) { return ImGui::CalcTextSize(label, nullptr, true).x; }
float button_width(const char* label) { return text_width(label) + 2.f * ImGui::GetStyle().FramePadding.x; }
float labelled_width(float item, const char* label) {
  const float text = text_width(label);
  return item + (text > 0.f ? ImGui::GetStyle().ItemInnerSpacing.x + text : 0.f);
}
float checkbox_width(const char* label) { return labelled_width(ImGui::GetFrameHeight(), label); }

}  // namespace inkray
