// JSON literals for the statistics the tools and the benchmark write by hand.
#ifndef CUT_PARAM_TOOLS_JSON_TEXT_H
#define CUT_PARAM_TOOLS_JSON_TEXT_H

#include <cmath>
#include <sstream>
#include <string>

namespace cut_tools {

/// A JSON string literal (quotes, backslashes and control characters escaped).
inline std::string json_string(const std::string& s)
{
  std::ostringstream out;
  out << '"';
  for(unsigned char c : s)
  {
    if(c == '"' || c == '\\') out << '\\' << c;
    else if(c < 0x20)
    {
      static const char* hex = "0123456789abcdef";
      out << "\\u00" << hex[c >> 4] << hex[c & 15];
    }
    else out << c;
  }
  out << '"';
  return out.str();
}

/// A JSON number with 10 significant digits; JSON has no infinity or NaN: those become null.
inline std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

} // namespace cut_tools

#endif
