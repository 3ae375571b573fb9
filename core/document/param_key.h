// A struct's parameters as bytes, for cache keys: two structs of one type have
// equal keys exactly when their parameters are equal. Written through the same
// parameter tables as everything else, so a new parameter is part of the key.
#pragma once

#include "core/document/desc.h"

#include <cstring>
#include <string>
#include <type_traits>

namespace inkray {

template <class T>
void append_key(std::string& key, const T& value);

namespace param_key_detail {

template <class T>
void append_bytes(std::string& key, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  key.append(bytes, sizeof(T));
}

struct Visitor {
  std::string* key;
  template <class T>
  void operator()(const Param&, const T& field) {
    append_key(*key, field);
  }
};

}  // namespace param_key_detail

template <class T>
void append_key(std::string& key, const T& value) {
  using namespace param_key_detail;
  if constexpr (std::is_same_v<T, std::string>) {
    append_bytes(key, value.size());
    key += value;
  } else if constexpr (requires {
                         value.index();
                         std::visit([](const auto&) {}, value);
                       }) {
    append_bytes(key, value.index());
    std::visit([&](const auto& alternative) { append_key(key, alternative); }, value);
  } else if constexpr (requires {
                         value.begin();
                         value.size();
                       }) {
    append_bytes(key, value.size());
    for (const auto& item : value) append_key(key, item);
  } else if constexpr (ParamGroup<T>) {
    Visitor visitor{&key};
    visit_params(value, visitor);
  } else {
    append_bytes(key, value);
  }
}

inline void append_key(std::string& key, const GraphNodeDesc& node) {
  append_key(key, node.id);
  append_key(key, node.data);
}

inline void append_key(std::string& key, const TransformDesc& t) {
  append_key(key, t.scale);
  append_key(key, t.translate);
  param_key_detail::append_bytes(key, t.rotate.size());
  for (const RotationDesc& r : t.rotate) append_key(key, r);
}

template <class T>
std::string param_key(const T& value) {
  std::string key;
  append_key(key, value);
  return key;
}

}  // namespace inkray
