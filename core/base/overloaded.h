// Overloaded: one visitor from several lambdas, for std::visit over a closed set.
// Give it one lambda per alternative and no `auto` catch-all, and a new
// alternative fails to compile at every visit until it is handled there.
#pragma once

namespace inkray {

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace inkray
