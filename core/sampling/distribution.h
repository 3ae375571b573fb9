// Discrete distribution over weights: picks an index with probability
// proportional to its weight and reuses the leftover of the uniform sample.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace inkray {

class DiscreteDistribution {
 public:
  DiscreteDistribution() = default;
  explicit DiscreteDistribution(std::span<const float> weights) {
    cdf_.resize(weights.size() + 1, 0.0);
    double total = 0.0;
    for (size_t i = 0; i < weights.size(); ++i) {
      total += weights[i] > 0.f ? double(weights[i]) : 0.0;
      cdf_[i + 1] = total;
    }
    total_ = total;
    if (total > 0.0)
      for (double& c : cdf_) c /= total;
  }

  bool empty() const { return cdf_.size() < 2 || total_ <= 0.0; }
  size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
  double total() const { return total_; }
  float pmf(size_t i) const { return float(cdf_[i + 1] - cdf_[i]); }

  // u in [0,1) -> index; *remapped is u rescaled to [0,1) within the chosen bin.
  size_t sample(float u, float* pmf_out, float* remapped = nullptr) const {
    const auto it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), double(u));
    size_t i = size_t(std::min<ptrdiff_t>(it - cdf_.begin() - 1, ptrdiff_t(size()) - 1));
    // Skip zero-weight bins that upper_bound can land on at their shared edge.
    while (i + 1 < size() && cdf_[i + 1] == cdf_[i]) ++i;
    const double width = cdf_[i + 1] - cdf_[i];
    *pmf_out = float(width);
    if (remapped)
      *remapped = width > 0.0 ? std::min(float((double(u) - cdf_[i]) / width), 0x1.fffffep-1f) : 0.f;
    return i;
  }

 private:
  std::vector<double> cdf_;
  double total_ = 0.0;
};

}  // namespace inkray
