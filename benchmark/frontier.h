// The baseline's frontier: E_s against E_d over runs of the baseline with
// other seam costs λ, so that a run can be compared with the baseline "at
// equal E_d" (the seam-length rule: E_s at most the baseline's at the same
// distortion) as well as point to point.
#ifndef CUT_PARAM_BENCHMARK_FRONTIER_H
#define CUT_PARAM_BENCHMARK_FRONTIER_H

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace cut_benchmark {

/// (E_d, E_s) of one run.
using Frontier_point = std::pair<double, double>;

/// E_s of the frontier of `points` at E_d `distortion`: the lower envelope of
/// the points (those that no point of lower or equal E_d beats on E_s; their
/// E_d rise strictly), linear between two of them, constant after the last;
/// NaN below the least E_d (the baseline never went that low) or without
/// points.
inline double frontier_seam_length(std::vector<Frontier_point> points, double distortion)
{
  const double none = std::numeric_limits<double>::quiet_NaN();
  std::sort(points.begin(), points.end());
  std::vector<Frontier_point> envelope;
  for(const Frontier_point& p : points)
    if(envelope.empty() || p.second < envelope.back().second) envelope.push_back(p);
  if(envelope.empty() || !(distortion >= envelope.front().first)) return none;
  for(std::size_t i = 0; i + 1 < envelope.size(); ++i)
  {
    const Frontier_point& a = envelope[i];
    const Frontier_point& b = envelope[i + 1];
    if(distortion <= b.first)
      return a.second + (distortion - a.first) / (b.first - a.first) * (b.second - a.second);
  }
  return envelope.back().second;
}

} // namespace cut_benchmark

#endif
