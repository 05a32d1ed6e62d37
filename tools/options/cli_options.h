// The rows of the option table (option_table.h) as CLI11 options: each row
// its flag, its help (with the library's default), its value checked against
// its range; the values given are collected one slot per row and copied into
// a Cut_parameterization_options, whose fields not given stay as the library
// leaves them (its rules decide what "unset" means).
#ifndef CUT_PARAM_TOOLS_OPTIONS_CLI_OPTIONS_H
#define CUT_PARAM_TOOLS_OPTIONS_CLI_OPTIONS_H

#include "option_table.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace cut_options {

/// The whole text is a finite number.
inline bool parse_cli_number(const std::string& text, double& value)
{
  std::size_t used = 0;
  try { value = std::stod(text, &used); } catch(const std::exception&) { return false; }
  return used != 0 && used == text.size() && std::isfinite(value);
}

/// "W:H", both positive numbers: the aspect ratio W / H.
inline bool parse_cli_ratio(const std::string& text, double& ratio)
{
  const std::size_t colon = text.find(':');
  if(colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) return false;
  double w = 0., h = 0.;
  if(!parse_cli_number(text.substr(0, colon), w) || !parse_cli_number(text.substr(colon + 1), h)) return false;
  ratio = w / h;
  return w > 0. && h > 0. && std::isfinite(ratio) && ratio > 0.;
}

/// The value of `text` for the row `spec` (a number, W:H, or a choice's index); false if invalid.
inline bool parse_cli_value(const Option_spec& spec, const std::string& text, double& value)
{
  if(spec.kind == Kind::CHOICE)
  {
    const std::vector<std::string> names = choice_names(spec);
    const auto it = std::find(names.begin(), names.end(), text);
    value = double(it - names.begin());
    return it != names.end();
  }
  if(spec.kind == Kind::RATIO) return parse_cli_ratio(text, value);
  return parse_cli_number(text, value) && in_range(spec, value);
}

/// `text` cut into lines of at most `width` characters, at spaces.
inline std::string wrapped(const std::string& text, std::size_t width = 62)
{
  std::string out, line;
  std::size_t start = 0;
  while(start < text.size())
  {
    std::size_t end = text.find(' ', start);
    if(end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if(!line.empty() && line.size() + 1 + word.size() > width) { out += line + "\n"; line.clear(); }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + line;
}

/// The help of a row: its text and the library's default.
inline std::string cli_help(const Option_spec& spec)
{
  std::string help = spec.help;
  const std::string d = default_text(spec);
  if(!d.empty() && spec.kind != Kind::FLAG && spec.kind != Kind::INVERTED_FLAG) help += " (default " + d + ")";
  return wrapped(help);
}

/// Adds the rows of the table to `app` (only those named in `only`, when it
/// is not empty), each in its group (or in `group` when it is not empty);
/// the values given land in `given`, which must outlive the parse. Returns the options added.
inline std::vector<CLI::Option*> add_cli_options(CLI::App& app, Given_options& given,
                                                const std::vector<std::string>& only = {},
                                                const std::string& group = "")
{
  const std::vector<Option_spec>& table = option_table();
  if(given.size() != table.size()) given.assign(table.size(), std::nullopt);
  std::vector<CLI::Option*> added;
  for(std::size_t i = 0; i < table.size(); ++i)
  {
    const Option_spec& spec = table[i];
    if(!only.empty() && std::find(only.begin(), only.end(), spec.name) == only.end()) continue;
    CLI::Option* option = nullptr;
    if(spec.kind == Kind::FLAG || spec.kind == Kind::INVERTED_FLAG)
    {
      const double value = spec.kind == Kind::FLAG ? 1. : 0.;
      option = app.add_flag_callback(spec.cli, [&given, i, value] { given[i] = value; }, cli_help(spec));
    }
    else
    {
      const std::string expected = spec.kind == Kind::CHOICE  ? std::string(spec.choices)
                                   : spec.kind == Kind::RATIO ? std::string("W:H, two positive numbers, e.g. 2:1")
                                                              : expected_text(spec);
      option = app.add_option_function<std::string>(
                    spec.cli,
                    [&given, i, spec](const std::string& text) {
                      double value = 0.;
                      parse_cli_value(spec, text, value); // checked by the validator
                      given[i] = value;
                    },
                    cli_help(spec))
                 ->type_name(spec.kind == Kind::CHOICE ? spec.choices
                             : spec.kind == Kind::RATIO ? "W:H"
                             : spec.kind == Kind::COUNT ? "N"
                                                        : "X")
                 ->check(CLI::Validator(
                   [spec, expected](std::string& text) -> std::string {
                     double value = 0.;
                     if(parse_cli_value(spec, text, value)) return {};
                     return "invalid value '" + text + "' (expected " + expected + ")";
                   },
                   ""));
    }
    option->group(group.empty() ? spec.group : group);
    added.push_back(option);
  }
  return added;
}

} // namespace cut_options

#endif
