// Which stages separate two documents (docs/architecture.md, "Stages"): the
// document is compared section by section, and within a struct parameter by
// parameter through its visit_params list, each difference naming the stage of
// the parameter that differs.
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

// Visits `before` (a copy: visit_params takes mutable structs) and finds each field's
// counterpart in `after` at the same offset: both are the same struct type.
class Visitor {
 public:
  Visitor(const void* before, const void* after, Stage section, StageSet* out)
      : before_(static_cast<const char*>(before)), after_(static_cast<const char*>(after)), section_(section),
        out_(out) {}

  template <class T>
  void operator()(const Param& p, T& field);

 private:
  const char* before_;
  const char* after_;
  Stage section_;
  StageSet* out_;
};

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
    T copy = before;
    stage_diff_detail::Visitor visitor(&copy, &after, section, &out);
    visit_params(copy, visitor);
  } else if (!(before == after)) {
    out.add(section);
  }
  return out;
}

template <class T>
void stage_diff_detail::Visitor::operator()(const Param& p, T& field) {
  const auto offset = reinterpret_cast<const char*>(&field) - before_;
  const T& other = *reinterpret_cast<const T*>(after_ + offset);
  out_->add(changed_stages(static_cast<const T&>(field), other, p.stage == Stage::inherit ? section_ : p.stage));
}

// One object: its shape is `geometry`, its transform `object`, the rest by parameter.
StageSet changed_stages(const ObjectDesc& before, const ObjectDesc& after);
// The whole document.
StageSet changed_stages(const SceneDesc& before, const SceneDesc& after);

}  // namespace inkray
