// Parsing of the benchmark's command line and CSV fields: splitting, trimming
// and strict number parsing (the whole field must be a number).
#ifndef CUT_PARAM_BENCHMARK_TEXT_PARSING_H
#define CUT_PARAM_BENCHMARK_TEXT_PARSING_H

#include <string>
#include <vector>

namespace cut_benchmark {

/// `s` split at every `sep`; a trailing separator gives a last empty item.
std::vector<std::string> split(const std::string& s, char sep);

/// `s` without leading and trailing blanks.
std::string trim(const std::string& s);

/// True if `s`, trimmed, is a number as a whole (written to `out`).
bool parse_double(const std::string& s, double& out);

/// True if `s`, trimmed, is a base-10 integer that fits an int (written to `out`).
bool parse_int(const std::string& s, int& out);

} // namespace cut_benchmark

#endif
