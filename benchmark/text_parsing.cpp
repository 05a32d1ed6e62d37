#include "text_parsing.h"

#include <cstdlib>
#include <limits>
#include <sstream>

namespace cut_benchmark {

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream is(s);
  while(std::getline(is, item, sep)) out.push_back(item);
  if(!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

std::string trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  if(b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool parse_double(const std::string& s, double& out)
{
  const std::string t = trim(s);
  if(t.empty()) return false;
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return end && *end == '\0';
}

bool parse_int(const std::string& s, int& out)
{
  const std::string t = trim(s);
  if(t.empty()) return false;
  char* end = nullptr;
  const long v = std::strtol(t.c_str(), &end, 10);
  if(!end || *end != '\0' || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    return false;
  out = int(v);
  return true;
}

} // namespace cut_benchmark
