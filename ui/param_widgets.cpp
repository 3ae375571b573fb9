#include "ui/param_widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace inkray {
namespace {

// Tooltips only while no button is held, so they never cover a slider being dragged.
bool hover_settled() { return ImGui::GetIO().MouseDownDuration[0] < 0.f; }

void tooltip(const Param& p) {
  if (!p.doc.empty() && ImGui::IsItemHovered() && hover_settled()) {
    ImGui::SetTooltip("%.*s", int(p.doc.size()), p.doc.data());
  }
}

std::string label_of(const Param& p) { return std::string(p.name); }

// Drag speed proportional to the range, or to the value for unbounded ones.
float drag_speed(const Param& p, float value) {
  if (std::isfinite(p.min) && std::isfinite(p.max) && p.max - p.min < 1e5) return float(p.max - p.min) / 500.f;
  return std::max(std::abs(value) * 0.01f, 0.01f);
}

float clamp_to(const Param& p, float v) {
  return float(std::clamp(double(v), std::isfinite(p.min) ? p.min : -1e30, std::isfinite(p.max) ? p.max : 1e30));
}

}  // namespace

void ParamWidgets::operator()(const Param& p, float& v) {
  float value = v;
  const bool slider = std::isfinite(p.min) && std::isfinite(p.max) && p.max - p.min <= 1000.0;
  const bool edited = slider ? ImGui::SliderFloat(label_of(p).c_str(), &value, float(p.min), float(p.max), "%.3f")
                             : ImGui::DragFloat(label_of(p).c_str(), &value, drag_speed(p, v), 0.f, 0.f, "%.4g");
  tooltip(p);
  if (edited && value != v) v = clamp_to(p, value), note(p);
}

void ParamWidgets::operator()(const Param& p, int& v) {
  int value = v;
  const bool slider = std::isfinite(p.min) && std::isfinite(p.max) && p.max - p.min <= 64.0;
  const bool edited = slider ? ImGui::SliderInt(label_of(p).c_str(), &value, int(p.min), int(p.max))
                             : ImGui::DragInt(label_of(p).c_str(), &value, std::max(std::abs(v) * 0.01f, 0.2f),
                                              int(std::max(p.min, -2e9)), int(std::min(p.max, 2e9)));
  tooltip(p);
  if (edited && value != v) v = int(clamp_to(p, float(value))), note(p);
}

void ParamWidgets::operator()(const Param& p, bool& v) {
  if (ImGui::Checkbox(label_of(p).c_str(), &v)) note(p);
  tooltip(p);
}

void ParamWidgets::operator()(const Param& p, Vec3& v) {
  Vec3 value = v;
  bool edited = false;
  if (p.kind == ParamKind::color) {
    edited = ImGui::ColorEdit3(label_of(p).c_str(), &value.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
  } else {
    edited = ImGui::DragFloat3(label_of(p).c_str(), &value.x, 0.01f, 0.f, 0.f, "%.3f");
  }
  tooltip(p);
  // The document only ever holds what the reader accepts, so every save opens again.
  for (int i = 0; i < 3; ++i) value[i] = clamp_to(p, value[i]);
  if (p.kind == ParamKind::direction && value == Vec3(0.f)) return;  // a zero direction has none
  if (edited && value != v) v = value, note(p);
}

void ParamWidgets::operator()(const Param& p, std::string& v) {
  std::string value = v;
  if (ImGui::InputText(label_of(p).c_str(), &value) && value != v) v = value, note(p);
  tooltip(p);
}

void ParamWidgets::operator()(const Param& p, ColorInput& v) {
  ImGui::PushID(label_of(p).c_str());
  if (edit_variant_type("##type", v)) note(p);
  ImGui::SameLine();
  ImGui::TextUnformatted(label_of(p).c_str());
  tooltip(p);
  if (Color* constant = std::get_if<Color>(&v)) {
    Param as_color = p;
    as_color.kind = ParamKind::color;
    (*this)(as_color, *constant);
  } else {
    ImGui::Indent();
    std::visit(
        [&](auto& alternative) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(alternative)>, Color>) visit_params(alternative, *this);
        },
        v);
    ImGui::Unindent();
  }
  ImGui::PopID();
}

void ParamWidgets::operator()(const Param& p, std::vector<Color>& v) {
  if (!begin_group(p)) return;
  for (size_t i = 0; i < v.size(); ++i) {
    ImGui::PushID(int(i));
    if (ImGui::ColorEdit3("##stop", &v[i].x, ImGuiColorEditFlags_Float)) note(p);
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) {
      v.erase(v.begin() + long(i));
      note(p);
      ImGui::PopID();
      break;
    }
    ImGui::PopID();
  }
  if (ImGui::SmallButton("+ stop")) {
    v.push_back(v.empty() ? Color(1.f) : v.back());
    note(p);
  }
  end_group();
}

bool ParamWidgets::choice_widget(const Param& p, int* index) {
  const int count = int(p.choices.size());
  const std::string preview = *index >= 0 && *index < count ? std::string(p.choices[size_t(*index)]) : "?";
  bool edited = false;
  if (ImGui::BeginCombo(label_of(p).c_str(), preview.c_str())) {
    for (int i = 0; i < count; ++i) {
      const std::string name(p.choices[size_t(i)]);
      if (ImGui::Selectable(name.c_str(), i == *index) && i != *index) *index = i, edited = true;
    }
    ImGui::EndCombo();
  }
  tooltip(p);
  return edited;
}

bool ParamWidgets::begin_group(const Param& p) {
  const bool open = ImGui::TreeNodeEx(label_of(p).c_str(), ImGuiTreeNodeFlags_SpanAvailWidth);
  tooltip(p);
  if (open) ImGui::PushID(label_of(p).c_str());
  return open;
}

void ParamWidgets::end_group() {
  ImGui::PopID();
  ImGui::TreePop();
}

void ParamWidgets::push_item(int index) {
  ImGui::PushID(index);
  ImGui::Separator();
}
void ParamWidgets::pop_item() { ImGui::PopID(); }
bool ParamWidgets::remove_button() { return ImGui::SmallButton("remove"); }
bool ParamWidgets::add_button() { return ImGui::SmallButton("+ add"); }

bool variant_type_combo_impl(const char* label, const std::vector<std::string_view>& names, int* index) {
  bool edited = false;
  const std::string preview = *index >= 0 && *index < int(names.size()) ? std::string(names[size_t(*index)]) : "?";
  if (ImGui::BeginCombo(label, preview.c_str())) {
    for (int i = 0; i < int(names.size()); ++i) {
      const std::string name(names[size_t(i)]);
      if (ImGui::Selectable(name.c_str(), i == *index) && i != *index) *index = i, edited = true;
    }
    ImGui::EndCombo();
  }
  return edited;
}

}  // namespace inkray
