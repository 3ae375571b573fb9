#include "ui/model/line_set_summary.h"

#include <string_view>
#include <utility>
#include <vector>

namespace inkray {
namespace {

// The names of the switches that are on, or `all` when every one is.
template <class Choice>
std::string chosen(const Choice& choice, std::string_view all, std::string_view none,
                   const std::vector<std::pair<bool Choice::*, std::string_view>>& names,
                   std::string_view separator) {
  std::string text;
  size_t on = 0;
  for (const auto& [member, name] : names) {
    if (!(choice.*member)) continue;
    text += (on++ ? std::string(separator) : std::string()) + std::string(name);
  }
  if (on == names.size()) return std::string(all);
  return on == 0 ? std::string(none) : text;
}

}  // namespace

std::string line_set_summary(const LineSetDesc& set) {
  std::vector<std::string> parts;
  parts.push_back(chosen(set.types, "all", "no line types",
                         {{&LineTypeChoice::silhouette, "silhouette"},
                          {&LineTypeChoice::object, "object"},
                          {&LineTypeChoice::material, "material"},
                          {&LineTypeChoice::crease, "crease"},
                          {&LineTypeChoice::depth, "depth"},
                          {&LineTypeChoice::intersection, "intersection"}},
                         ", "));
  if (set.visibility == LineVisibility::hidden) parts.push_back("hidden");
  if (set.visibility == LineVisibility::both) parts.push_back("visible and hidden");
  const std::string paths = chosen(set.paths, "", "no paths",
                                   {{&LinePathChoice::direct, "direct"},
                                    {&LinePathChoice::reflected, "in mirrors"},
                                    {&LinePathChoice::refracted, "through glass"}},
                                   " and ");
  if (!paths.empty()) parts.push_back(paths);
  if (!set.objects.empty()) parts.push_back("objects " + set.objects);
  if (!set.materials.empty()) parts.push_back("materials " + set.materials);
  // "all" alone reads as every line; with more after it, as every type.
  if (parts.size() == 1 && parts[0] == "all") return "all lines";
  if (parts[0] == "all") parts[0] = "all types";
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

}  // namespace inkray
