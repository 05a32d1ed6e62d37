#include "table_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace cut_benchmark {

std::string fixed(double x, int digits)
{
  if(std::isnan(x)) return "-";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  // Huge values (a failed reference result) in scientific notation.
  if(std::abs(x) >= 1e6) std::snprintf(buf, sizeof buf, "%.3g", x);
  else std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string time_text(double t)
{
  if(!(t < 0.001) || t <= 0.) return fixed(t, 3);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2g", t);
  return buf;
}

std::string full(double x)
{
  if(std::isnan(x)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

void print_table(std::ostream& os, const std::vector<Column>& columns,
                 const std::vector<std::vector<std::string>>& cells)
{
  std::vector<std::size_t> width(columns.size());
  for(std::size_t c = 0; c < columns.size(); ++c)
  {
    width[c] = columns[c].title.size();
    for(const auto& row : cells) width[c] = std::max(width[c], row[c].size());
  }
  auto line = [&](const std::vector<std::string>& row) {
    std::string s;
    for(std::size_t c = 0; c < columns.size(); ++c)
    {
      const std::string pad(width[c] - row[c].size(), ' ');
      if(c) s += "  ";
      s += columns[c].left ? row[c] + pad : pad + row[c];
    }
    while(!s.empty() && s.back() == ' ') s.pop_back();
    os << s << "\n";
  };
  std::vector<std::string> titles;
  for(const auto& c : columns) titles.push_back(c.title);
  line(titles);
  std::size_t total = 0;
  for(auto w : width) total += w;
  os << std::string(total + 2 * (columns.size() - 1), '-') << "\n";
  for(const auto& row : cells) line(row);
}

std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for(char c : s) { if(c == '"') q += '"'; q += c; }
  return q + "\"";
}

} // namespace cut_benchmark
