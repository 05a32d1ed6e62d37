// Median of a sample (the mean of the two middle values for an even count).
#ifndef CUT_PARAM_BENCHMARK_MEDIAN_H
#define CUT_PARAM_BENCHMARK_MEDIAN_H

#include <algorithm>
#include <limits>
#include <vector>

namespace cut_benchmark {

/// NaN for an empty sample.
inline double median(std::vector<double> v)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace cut_benchmark

#endif
