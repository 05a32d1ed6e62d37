// How the benchmark writes its results: numbers as text, an aligned text
// table and fields of CSV files (the JSON of --scaling: nlohmann-json, in scaling.cpp).
#ifndef CUT_PARAM_BENCHMARK_TABLE_OUTPUT_H
#define CUT_PARAM_BENCHMARK_TABLE_OUTPUT_H

#include <iosfwd>
#include <string>
#include <vector>

namespace cut_benchmark {

/// `digits` decimals; "-" for NaN, "inf"/"-inf", and 3 significant digits from 1e6 on.
std::string fixed(double x, int digits);

/// Seconds with 3 decimals; sub-millisecond times with 2 significant digits.
std::string time_text(double t);

/// 10 significant digits (CSV); "" for NaN.
std::string full(double x);

struct Column
{
  std::string title;
  bool left = false;
};

/// Columns padded to their widest cell (left- or right-aligned), a rule under
/// the titles.
void print_table(std::ostream& os, const std::vector<Column>& columns,
                 const std::vector<std::vector<std::string>>& cells);

/// A CSV field, quoted if it has to be.
std::string csv_field(const std::string& s);

} // namespace cut_benchmark

#endif
