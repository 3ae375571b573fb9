// Command lines as tables: each option of inkray-render and the editor is a row with
// its spellings, the number of words it takes and what it does with them, and one loop
// reads argv against the table (parse_options). An option that sets a document
// parameter (--spp, --width, --seed) takes its range from that parameter's row in its
// parameter table (param_range), so the command line and the scene format cannot
// disagree on what a value may be (docs/architecture.md, "Parameter tables").
#pragma once

#include "app/cli_numbers.h"
#include "core/document/params.h"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace inkray::cli {

using Words = std::span<const std::string_view>;

template <class Options>
struct Option {
  std::vector<std::string_view> names;  // "-o", "--output"
  int values = 0;                       // words it takes after it
  // Applies the words; "" when they are good, else the message naming the option.
  std::function<std::string(Options&, Words)> apply;
  bool ends = false;  // reading stops after it (--help)
};

template <class T>
struct Range {
  T lo, hi;
};

// The range of `member`'s row in the parameter table of S, as T.
template <class T, class S, class M>
Range<T> param_range(M S::*member) {
  std::optional<Range<T>> found;
  std::apply(
      [&](const auto&... r) {
        const auto match = [&](const auto& row) {
          if constexpr (std::is_same_v<decltype(row.member), M S::*>)
            if (row.member == member) found = Range<T>{T(row.param.min), T(row.param.max)};
        };
        (match(r), ...);
      },
      ParamTable<S>::rows);
  return found.value();  // a member without a row is a programming error
}

// An option whose one word is a number in `range`, stored in the field `get(options)`
// returns (a number or an optional one): "--threads: expected an integer in [1, 1024],
// got \"many\"" otherwise.
template <class Options, class Get, class T>
requires std::is_invocable_v<Get, Options&> Option<Options> number_option(std::vector<std::string_view> names,
                                                                          Get get, Range<T> range) {
  const std::string_view name = names.back();
  return {std::move(names), 1, [=](Options& o, Words w) {
            T value{};
            std::string problem = read_option_number(name, w[0], range.lo, range.hi, &value);
            if (problem.empty()) get(o) = value;
            return problem;
          }};
}
template <class Options, class Member, class T>
Option<Options> number_option(std::vector<std::string_view> names, Member Options::*member, Range<T> range) {
  return number_option<Options>(
      std::move(names), [member](Options& o) -> Member& { return o.*member; }, range);
}

// An option whose one word is stored as it is (a file, a name) in `get(options)`.
template <class Options, class Get>
requires std::is_invocable_v<Get, Options&> Option<Options> text_option(std::vector<std::string_view> names,
                                                                        Get get) {
  return {std::move(names), 1, [=](Options& o, Words w) {
            auto& field = get(o);
            field = std::remove_reference_t<decltype(field)>(std::string(w[0]));
            return std::string();
          }};
}
template <class Options, class Member>
Option<Options> text_option(std::vector<std::string_view> names, Member Options::*member) {
  return text_option<Options>(std::move(names), [member](Options& o) -> Member& { return o.*member; });
}

// An option without words that sets a flag.
template <class Options>
Option<Options> flag_option(std::vector<std::string_view> names, bool Options::*member, bool ends = false) {
  return {std::move(names), 0,
          [=](Options& o, Words) {
            o.*member = true;
            return std::string();
          },
          ends};
}

// Reads argv[1..argc) against `table`. Words that are no option go to `positional`
// ("" or why it refuses them); a word starting with '-' that no row names is refused.
// Returns "" or the first problem, one line.
template <class Options>
std::string parse_options(std::span<const Option<Options>> table, int argc, const char* const* argv,
                          Options& o,
                          const std::function<std::string(Options&, std::string_view)>& positional) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const Option<Options>* option = nullptr;
    for (const Option<Options>& row : table)
      for (std::string_view name : row.names)
        if (name == arg) option = &row;
    if (!option) {
      if (!arg.empty() && arg[0] == '-') return "unknown option \"" + std::string(arg) + "\" (see --help)";
      if (std::string problem = positional(o, arg); !problem.empty()) return problem;
      continue;
    }
    std::vector<std::string_view> words;
    for (int k = 0; k < option->values; ++k) {
      if (i + 1 >= argc) return std::string(arg) + ": missing value";
      words.emplace_back(argv[++i]);
    }
    if (std::string problem = option->apply(o, words); !problem.empty()) return problem;
    if (option->ends) return {};
  }
  return {};
}

}  // namespace inkray::cli
