// Generic access to the closed sets in desc.h: variants whose alternatives carry a
// static `type_name`. The JSON reader and writer (and the editor's type menus)
// iterate the alternatives here instead of repeating each set by hand.
#pragma once

#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace inkray {

// An alternative that is written as a JSON object with a "type" key.
template <class T>
concept Tagged = requires {
  { T::type_name } -> std::convertible_to<std::string_view>;
};

namespace detail {
template <class Variant, class F, std::size_t... I>
constexpr void for_each_alternative_impl(F& f, std::index_sequence<I...>) {
  (f(std::type_identity<std::variant_alternative_t<I, Variant>>{}), ...);
}
}  // namespace detail

// Calls f(std::type_identity<Alternative>{}) for each alternative, in declaration order.
template <class Variant, class F>
constexpr void for_each_alternative(F&& f) {
  detail::for_each_alternative_impl<Variant>(f, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

// "diffuse, conductor, ...": the tagged alternatives' names, for messages and docs.
template <class Variant>
std::string type_name_list() {
  std::string list;
  for_each_alternative<Variant>([&]<class T>(std::type_identity<T>) {
    if constexpr (Tagged<T>) {
      if (!list.empty()) list += ", ";
      list += T::type_name;
    }
  });
  return list;
}

// Replaces v by a default-constructed alternative named `type`; false (v unchanged)
// when no tagged alternative has that name.
template <class Variant>
bool emplace_by_type_name(Variant& v, std::string_view type) {
  bool found = false;
  for_each_alternative<Variant>([&]<class T>(std::type_identity<T>) {
    if constexpr (Tagged<T>) {
      if (!found && T::type_name == type) {
        v.template emplace<T>();
        found = true;
      }
    }
  });
  return found;
}

// The type_name of v's current alternative; empty for an untagged one (a constant colour).
template <class Variant>
std::string_view type_name_of(const Variant& v) {
  return std::visit(
      []<class T>(const T&) -> std::string_view {
        if constexpr (Tagged<T>) {
          return T::type_name;
        } else {
          return {};
        }
      },
      v);
}

}  // namespace inkray
