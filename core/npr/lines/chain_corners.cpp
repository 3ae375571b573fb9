// Corners of chains.
#include "core/npr/lines/chain_corners.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// The point kCornerReachPx of chain from point i, walking by `step` (+1 ahead, -1
// behind); -1 when an open chain ends first.
int reach_from(const Chain& chain, int i, int step) {
  const int n = int(chain.points.size());
  float walked = 0.f;
  int at = i;
  for (int k = 0; k < n - 1; ++k) {
    int next = at + step;
    if (chain.closed) next = (next + n) % n;
    if (next < 0 || next >= n) return -1;
    walked += glm::length(chain.points[size_t(next)].p - chain.points[size_t(at)].p);
    at = next;
    if (walked >= kCornerReachPx) return at;
  }
  return -1;
}

// Points first to last, wrapping round a closed chain; all the way round back to
// `first` when they are the same.
Chain piece_of(const Chain& chain, int first, int last) {
  Chain piece = chain;  // every label, covers included
  piece.closed = false;
  piece.points.clear();
  const int n = int(chain.points.size());
  // A cut end is a corner, not a crossing: only the chain's own ends keep theirs.
  piece.ends_at_crossing = {!chain.closed && first == 0 && chain.ends_at_crossing[0],
                            !chain.closed && last == n - 1 && chain.ends_at_crossing[1]};
  const int count = last == first ? n + 1 : (last - first + n) % n + 1;
  for (int k = 0; k < count; ++k) piece.points.push_back(chain.points[size_t((first + k) % n)]);
  return piece;
}

}  // namespace

std::vector<float> chain_turns(const Chain& chain) {
  const int n = int(chain.points.size());
  std::vector<float> turns(size_t(n), 0.f);
  for (int i = 0; i < n; ++i) {
    const int behind = reach_from(chain, i, -1), ahead = reach_from(chain, i, +1);
    if (behind < 0 || ahead < 0) continue;
    const Vec2 p = chain.points[size_t(i)].p;
    const Vec2 in = p - chain.points[size_t(behind)].p, out = chain.points[size_t(ahead)].p - p;
    const float lengths = glm::length(in) * glm::length(out);
    if (!(lengths > 0.f)) continue;
    const float cosine = std::clamp(glm::dot(in, out) / lengths, -1.f, 1.f);
    turns[size_t(i)] = glm::degrees(std::acos(cosine));
  }
  return turns;
}

std::vector<Chain> split_at_corners(const Chain& chain, float corner_angle) {
  const int n = int(chain.points.size());
  if (!(corner_angle > 0.f) || n < 3) return {chain};
  const std::vector<float> turns = chain_turns(chain);
  const float limit = 180.f - corner_angle;
  // One cut per run of points over the limit, at its sharpest: a rounded corner
  // turns over several points. A closed chain's runs may wrap past its first
  // point, so they are walked from a point under the limit.
  int start = 0;
  if (chain.closed) {
    while (start < n && turns[size_t(start)] > limit) ++start;
    if (start == n) return {chain};  // all corner: nothing sensible to cut
  }
  std::vector<int> cuts;
  int best = -1;
  for (int k = 0; k <= n; ++k) {
    const int i = chain.closed ? (start + k) % n : k;
    const bool over = k < n && turns[size_t(i)] > limit;
    if (over && (best < 0 || turns[size_t(i)] > turns[size_t(best)])) best = i;
    if (!over && best >= 0) cuts.push_back(best), best = -1;
  }
  if (cuts.empty()) return {chain};
  std::vector<Chain> pieces;
  if (chain.closed) {
    std::sort(cuts.begin(), cuts.end());
    for (size_t c = 0; c < cuts.size(); ++c)
      pieces.push_back(piece_of(chain, cuts[c], cuts[(c + 1) % cuts.size()]));
    return pieces;
  }
  int first = 0;
  for (int cut : cuts) pieces.push_back(piece_of(chain, first, cut)), first = cut;
  pieces.push_back(piece_of(chain, first, n - 1));
  return pieces;
}

}  // namespace inkray
