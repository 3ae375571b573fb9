// Which stages separate two documents (docs/architecture.md, "Stages"): the
// document is compared section by section, and within a struct parameter by
// parameter through its parameter table (for_each_param_pair), each difference
// naming the stage of the parameter that differs.
#pragma once

#include "core/document/desc.h"

#include <cstdint>
#include <string>
#include <type_traits>

namespace inkray {

struct StageSet {
  uint32_t bits = 0;

  bool has(Stage s) const { return bits & (1u << unsigned(s)); }
  void add(Stage s) { bits |= 1u << unsigned(s); }
  void add(StageSet other) { bits |= other.bits; }
  bool empty() const { return bits == 0; }
  // True when every stage present is one of `allowed`.
  bool within(std::initializer_list<Stage> allowed) const {
    uint32_t mask = 0;
    for (Stage s : allowed) mask |= 1u << unsigned(s);
    return (bits & ~mask) == 0;
  }
  // "material, light", for logs and test messages.
  std::string names() const {
    std::string text;
    for (int s = 0; s < kStageCount; ++s)
      if (has(Stage(s))) text += (text.empty() ? "" : ", ") + std::string(kStageNames[size_t(s)]);
    return text.empty() ? "none" : text;
  }
  bool operator==(const StageSet&) const = default;
};

namespace stage_diff_detail {

template <class T>
struct is_variant : std::false_type {};
template <class... A>
struct is_variant<std::variant<A...>> : std::true_type {};

}  // namespace stage_diff_detail

// Stages of the parameters that differ between two structs of one type; a
// parameter without its own stage counts as `section`. A variant whose
// alternatives differ counts as `section` as a whole.
template <class T>
StageSet changed_stages(const T& before, const T& after, Stage section) {
  StageSet out;
  if constexpr (stage_diff_detail::is_variant<T>::value) {
    if (before.index() != after.index()) {
      out.add(section);
    } else {
      std::visit(
          [&](const auto& b) {
            using A = std::decay_t<decltype(b)>;
            out.add(changed_stages(b, std::get<A>(after), section));
          },
          before);
    }
  } else if constexpr (ParamGroup<T>) {
    for_each_param_pair(before, after, [&](const Param& p, const auto& b, const auto& a) {
      out.add(changed_stages(b, a, p.stage == Stage::inherit ? section : p.stage));
    });
  } else if (!(before == after)) {
    out.add(section);
  }
  return out;
}

// One object: its shape is `geometry`, its transform `object`, the rest by parameter.
StageSet changed_stages(const ObjectDesc& before, const ObjectDesc& after);
// The whole document.
StageSet changed_stages(const SceneDesc& before, const SceneDesc& after);

}  // namespace inkray
