#include "ui/widgets/param_widgets.h"

#include "core/document/animation.h"
#include "core/document/animation_edit.h"
#include "core/document/param_text.h"
#include "ui/widgets/path_field.h"
#include "ui/model/scene_edits.h"
#include "ui/widgets/widget_report.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace inkray {
namespace {

// Tooltips only while no button is held, so they never cover a slider being dragged.
bool hover_settled() { return ImGui::GetIO().MouseDownDuration[0] < 0.f; }

// The label shown; the JSON key alone is the ImGui id, so relabelling never changes an id.
std::string label_of(const Param& p) { return param_label(p) + "###" + std::string(p.name); }

// Unbounded values drag at a speed proportional to the value.
float drag_speed(float value, float least) { return std::max(std::abs(value) * 0.01f, least); }

double clamp_to(const Param& p, double v) {
  return std::clamp(v, std::isfinite(p.min) ? p.min : -1e30, std::isfinite(p.max) ? p.max : 1e30);
}

ImGuiSliderFlags slider_flags(const SliderRange& range) {
  return range.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
}

const ImVec4 kProblemColour(1.f, 0.35f, 0.3f, 1.f);

}  // namespace

void draw_key_diamond(ImDrawList* draw, float x, float y, float r, unsigned fill, unsigned outline) {
  const ImVec2 top(x, y - r), right(x + r, y), bottom(x, y + r), left(x - r, y);
  if (fill != 0) draw->AddQuadFilled(top, right, bottom, left, fill);
  if (outline != 0) draw->AddQuad(top, right, bottom, left, outline, std::max(1.f, r * 0.3f));
}

std::string ParamWidgets::field_path(std::string_view name) const {
  std::string param = key_group;
  param += (param.empty() || path_.empty() ? "" : ".") + path_;
  if (!name.empty()) param += (param.empty() || param.back() == '.' ? "" : ".") + std::string(name);
  if (!param.empty() && param.back() == '.') param.pop_back();  // the group being drawn
  return key_path(*keys->document, key_item, param);
}

void ParamWidgets::key_marks(const Param& p, float mark_x) {
  if (!keys || !keys->document) return;
  const SceneDesc& doc = *keys->document;
  const std::string path = field_path(p.name);
  if (path.empty() || !animation_target(doc, path, nullptr)) return;
  const KeyState state = key_state(doc, path, doc.render.frame);
  if (state != KeyState::none) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const float r = ImGui::GetFontSize() * 0.3f;
    const float x = mark_x >= 0.f ? mark_x : hi.x + ImGui::GetStyle().ItemInnerSpacing.x + r;
    const float y = 0.5f * (lo.y + hi.y);
    if (state == KeyState::keyed) {
      // Over a colour the yellow needs an edge to be seen.
      draw_key_diamond(ImGui::GetWindowDrawList(), x, y, r, kKeyFill, mark_x >= 0.f ? 0xFF202020u : 0u);
    } else {
      draw_key_diamond(ImGui::GetWindowDrawList(), x, y, r, 0, kAnimatedMark);
    }
  }
  if (keys->report) widget_report::item("param:" + path);
  if (ImGui::IsItemHovered()) keys->hovered = path;
  if (ImGui::IsItemFocused()) keys->focused = path;
  if (ImGui::BeginPopupContextItem(("keys:" + path).c_str())) {
    using Action = KeyTargets::Action;
    const auto choose = [&](Action a) { keys->action = a, keys->action_path = path; };
    if (ImGui::MenuItem("Insert key", "I")) choose(Action::insert);
    if (keys->report) widget_report::item("keys_menu.insert");
    if (ImGui::MenuItem("Delete key", "Alt+I", false, state == KeyState::keyed)) choose(Action::remove);
    if (keys->report) widget_report::item("keys_menu.delete");
    if (ImGui::MenuItem("Clear keys", nullptr, false, state != KeyState::none)) choose(Action::clear);
    if (keys->report) widget_report::item("keys_menu.clear");
    ImGui::EndPopup();
  }
}

void ParamWidgets::finish(const Param& p, bool typed_value) {
  if (ImGui::IsItemHovered() && hover_settled())
    ImGui::SetTooltip("%s", param_tooltip(p, typed_value).c_str());
  if (problem_message.empty() || problem_param != path_ + std::string(p.name)) return;
  ImGui::PushStyleColor(ImGuiCol_Text, kProblemColour);
  ImGui::PushTextWrapPos(0.f);
  ImGui::TextUnformatted(problem_message.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

// Sliders span the soft range; Ctrl+click types any value, which the hard range clamps.
void ParamWidgets::operator()(const Param& p, float& v) {
  float value = v;
  bool edited = false;
  if (const auto range = slider_range(p)) {
    const std::string format = "%." + std::to_string(slider_decimals(*range)) + "f";
    edited = ImGui::SliderFloat(label_of(p).c_str(), &value, float(range->min), float(range->max),
                                format.c_str(), slider_flags(*range));
  } else {
    edited = ImGui::DragFloat(label_of(p).c_str(), &value, drag_speed(v, 0.01f), 0.f, 0.f, "%.4g");
  }
  key_marks(p);
  finish(p, true);
  if (edited && value != v && std::isfinite(value)) v = float(clamp_to(p, value)), note(p);
}

void ParamWidgets::operator()(const Param& p, int& v) {
  int value = v;
  bool edited = false;
  if (const auto range = slider_range(p)) {
    edited = ImGui::SliderInt(label_of(p).c_str(), &value, int(range->min), int(range->max), "%d",
                              slider_flags(*range));
  } else {
    edited = ImGui::DragInt(label_of(p).c_str(), &value, drag_speed(float(v), 0.2f),
                            int(std::max(p.min, -2e9)), int(std::min(p.max, 2e9)));
  }
  key_marks(p);
  finish(p, true);
  if (edited && value != v) v = int(clamp_to(p, value)), note(p);
}

void ParamWidgets::operator()(const Param& p, bool& v) {
  if (ImGui::Checkbox(label_of(p).c_str(), &v)) note(p);
  key_marks(p);
  finish(p, false);
}

void ParamWidgets::operator()(const Param& p, Vec3& v) {
  Vec3 value = v;
  bool edited = false;
  if (p.kind == ParamKind::color) {
    // The hue wheel picker also offers HSV and hex fields; HDR where the range allows.
    ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_PickerHueWheel;
    if (p.max > 1.0) flags |= ImGuiColorEditFlags_HDR;
    const std::string label = unlabelled_ ? "###" + std::string(p.name) : label_of(p);
    edited = ImGui::ColorEdit3(label.c_str(), &value.x, flags);
  } else {
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    edited =
        ImGui::DragFloat3(label_of(p).c_str(), &value.x, drag_speed(largest, 0.01f) * 0.5f, 0.f, 0.f, "%.3f");
  }
  key_marks(p);
  finish(p, true);
  // The document only ever holds what the reader accepts, so every save opens again.
  for (int i = 0; i < 3; ++i) value[i] = float(clamp_to(p, std::isfinite(value[i]) ? value[i] : v[i]));
  if (p.kind == ParamKind::direction && value == Vec3(0.f)) return;  // a zero direction has none
  if (edited && value != v) v = value, note(p);
}

void ParamWidgets::operator()(const Param& p, std::string& v) {
  if (p.refers_to != Ref::none && scene) {
    if (reference_widget(p, &v)) note(p);
    finish(p, false);
    return;
  }
  std::string value = v;
  bool edited = false;
  if (p.kind == ParamKind::path) {
    std::error_code ec;
    const std::filesystem::path folder =
        scene && !scene->base_dir.empty() ? scene->base_dir : std::filesystem::current_path(ec);
    edited = path_field(label_of(p).c_str(), p, &value, folder);
  } else {
    edited = ImGui::InputText(label_of(p).c_str(), &value);
  }
  if (edited && value != v) v = value, note(p);
  finish(p, false);
}

// The names that exist of the kind the parameter refers to.
bool ParamWidgets::reference_widget(const Param& p, std::string* value) {
  std::vector<std::string_view> names;
  const auto add = [&](const auto& items) {
    for (const auto& item : items)
      if (!(p.refers_to == Ref::material && item.name == self_name)) names.push_back(item.name);
  };
  switch (p.refers_to) {
    case Ref::material:
      add(scene->materials);
      break;
    case Ref::object:
      add(scene->objects);
      break;
    case Ref::light:
      add(scene->lights);
      break;
    case Ref::none:
      break;
  }
  const bool known = std::find(names.begin(), names.end(), *value) != names.end();
  const std::string preview = value->empty() ? "(choose)" : known ? *value : *value + " (missing)";
  bool edited = false;
  if (ImGui::BeginCombo(label_of(p).c_str(), preview.c_str())) {
    for (std::string_view name : names) {
      const std::string shown(name);
      if (ImGui::Selectable(shown.c_str(), shown == *value) && shown != *value) *value = shown, edited = true;
    }
    ImGui::EndCombo();
  }
  return edited;
}

void ParamWidgets::operator()(const Param& p, ColorInput& v) {
  ImGui::PushID(std::string(p.name).c_str());
  if (edit_variant_type("##type", v)) note(p);
  ImGui::SameLine();
  ImGui::TextUnformatted(param_label(p).c_str());
  finish(p, false);
  if (Color* constant = std::get_if<Color>(&v)) {
    // The row above names it; the swatch row needs no second label.
    Param as_color = p;
    as_color.kind = ParamKind::color;
    unlabelled_ = true;
    (*this)(as_color, *constant);
    unlabelled_ = false;
  } else {
    ImGui::Indent();
    path_lengths_.push_back(path_.size());
    path_ += std::string(p.name) + ".";
    std::visit(
        [&](auto& alternative) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(alternative)>, Color>)
            visit_params(alternative, *this);
        },
        v);
    path_.resize(path_lengths_.back());
    path_lengths_.pop_back();
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

// Choice names read as labels too ("rgb_to_hsv" -> "RGB to HSV"); the file keeps the name.
bool ParamWidgets::choice_widget(const Param& p, int* index) {
  const int count = int(p.choices.size());
  const std::string preview = *index >= 0 && *index < count ? derived_label(p.choices[size_t(*index)]) : "?";
  bool edited = false;
  if (ImGui::BeginCombo(label_of(p).c_str(), preview.c_str())) {
    for (int i = 0; i < count; ++i) {
      const std::string name = derived_label(p.choices[size_t(i)]) + "##" + std::string(p.choices[size_t(i)]);
      if (ImGui::Selectable(name.c_str(), i == *index) && i != *index) *index = i, edited = true;
    }
    ImGui::EndCombo();
  }
  key_marks(p);
  finish(p, false);
  return edited;
}

bool ParamWidgets::begin_group(const Param& p) {
  const bool open = ImGui::TreeNodeEx(label_of(p).c_str(), ImGuiTreeNodeFlags_SpanAvailWidth);
  finish(p, false);
  if (!open) return false;
  ImGui::PushID(std::string(p.name).c_str());
  path_lengths_.push_back(path_.size());
  path_ += std::string(p.name) + ".";
  return true;
}

void ParamWidgets::end_group() {
  path_.resize(path_lengths_.back());
  path_lengths_.pop_back();
  ImGui::PopID();
  ImGui::TreePop();
}

void ParamWidgets::push_item(const Param& p, int index) {
  ImGui::PushID(index);
  ImGui::Separator();
  // A list's entries: "stops[1].position"; the group already added "stops.".
  path_lengths_.push_back(path_.size());
  path_.resize(path_.size() - 1 - p.name.size());
  path_ += std::string(p.name) + "[" + std::to_string(index) + "].";
}
void ParamWidgets::pop_item() {
  path_.resize(path_lengths_.back());
  path_lengths_.pop_back();
  ImGui::PopID();
}
ParamWidgets::ItemAction ParamWidgets::item_buttons(bool can_go_up, bool can_go_down) {
  ItemAction action = ItemAction::none;
  if (ImGui::SmallButton("remove")) action = ItemAction::remove;
  if (can_go_up) {
    ImGui::SameLine();
    if (ImGui::SmallButton("up")) action = ItemAction::up;
  }
  if (can_go_down) {
    ImGui::SameLine();
    if (ImGui::SmallButton("down")) action = ItemAction::down;
  }
  return action;
}

bool ParamWidgets::preset_combo(std::span<const std::string_view> names, int* chosen) {
  // Scripts find the combo by its group's path ("preset:outlines/sets/ink/style") and
  // its entries by name ("preset_menu.pencil").
  const bool report = keys && keys->report && keys->document;
  bool picked = false;
  const bool open = ImGui::BeginCombo("Preset", "choose...");
  if (report) widget_report::item("preset:" + field_path({}));
  if (open) {
    for (int i = 0; i < int(names.size()); ++i) {
      if (ImGui::Selectable(derived_label(names[size_t(i)]).c_str(), false)) *chosen = i, picked = true;
      if (report) widget_report::item("preset_menu." + std::string(names[size_t(i)]));
    }
    ImGui::EndCombo();
  }
  return picked;
}
bool ParamWidgets::add_button() { return ImGui::SmallButton("+ add"); }

bool variant_type_combo_impl(const char* label, const std::vector<std::string_view>& names, int* index) {
  bool edited = false;
  const std::string preview =
      *index >= 0 && *index < int(names.size()) ? derived_label(names[size_t(*index)]) : "?";
  if (ImGui::BeginCombo(label, preview.c_str())) {
    for (int i = 0; i < int(names.size()); ++i) {
      const std::string name = derived_label(names[size_t(i)]) + "##" + std::string(names[size_t(i)]);
      if (ImGui::Selectable(name.c_str(), i == *index) && i != *index) *index = i, edited = true;
    }
    ImGui::EndCombo();
  }
  return edited;
}

}  // namespace inkray
