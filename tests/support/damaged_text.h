// Random damage to a valid file's text, for tests that a reader answers any edit of it
// without throwing or crashing.
#pragma once

#include <cstddef>
#include <random>
#include <string>

namespace inkray::testing {

struct TextDamage {
  std::string alphabet;  // characters written in
  std::size_t max_erase = 8, max_copy = 24;
  bool inserts = false;  // a character inserted as a fourth kind of edit
};

// One to four edits of `text`: a character replaced, a run erased, a run copied to
// elsewhere, or (with `inserts`) a character inserted.
inline std::string damaged(std::string text, std::mt19937& rng, const TextDamage& d) {
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = rng() % text.size();
    switch (rng() % (d.inserts ? 4 : 3)) {
      case 0:
        text[at] = d.alphabet[rng() % d.alphabet.size()];
        break;
      case 1:
        text.erase(at, 1 + rng() % d.max_erase);
        break;
      case 2:
        text.insert(at, text.substr(rng() % text.size(), 1 + rng() % d.max_copy));
        break;
      default:
        text.insert(at, 1, d.alphabet[rng() % d.alphabet.size()]);
        break;
    }
  }
  return text;
}

}  // namespace inkray::testing
