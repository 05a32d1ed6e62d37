// Writes the option table (option_table.h) as JSON, for the front ends that
// cannot read C++: the Blender add-on builds its properties and its
// command-line translation from it (build/blender/.../option_table.json),
// and tools/tests/check_option_coverage.py checks the front ends against it.
//   export_option_table FILE.json
#include "option_table.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: export_option_table FILE.json\n";
    return 2;
  }
  using cut_options::Kind;
  namespace SMP = CGAL::Surface_mesh_parameterization;
  const char* kinds[] = {"real", "count", "flag", "inverted_flag", "ratio", "choice"};
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for(const cut_options::Option_spec& spec : cut_options::option_table())
  {
    nlohmann::ordered_json row;
    row["name"] = spec.name;
    row["kind"] = kinds[static_cast<int>(spec.kind)];
    row["cli"] = spec.cli;
    row["python"] = spec.python;
    row["blender"] = spec.blender;
    // the library's default as the front ends offer it; null: not given (the library's rule decides)
    const std::optional<double> d = cut_options::front_end_default(spec);
    if(!d) row["default"] = nullptr;
    else if(spec.kind == Kind::FLAG || spec.kind == Kind::INVERTED_FLAG) row["default"] = *d != 0.;
    else if(spec.kind == Kind::COUNT || spec.kind == Kind::CHOICE) row["default"] = static_cast<long long>(*d);
    else row["default"] = *d;
    // what the library uses when the option is not given (its rule, evaluated here, not restated)
    const SMP::Cut_parameterization_options defaults;
    const std::string name = spec.name;
    if(name == "bounding_box_aspect_ratio") row["unset_value"] = defaults.bounding_box_aspect_ratio_value();
    else if(name == "bounding_box_stiffness") row["unset_value"] = defaults.bounding_box_stiffness_value();
    else if(name == "bounding_box_distortion_budget")
      row["unset_value"] = defaults.bounding_box_distortion_budget_value();
    else row["unset_value"] = row["default"];
    row["min"] = spec.min;
    row["min_open"] = spec.min_open;
    row["max"] = std::isfinite(spec.max) ? nlohmann::ordered_json(spec.max) : nlohmann::ordered_json();
    row["choices"] = cut_options::choice_names(spec);
    row["expected"] = cut_options::expected_text(spec);
    row["group"] = spec.group;
    row["help"] = spec.help;
    rows.push_back(row);
  }
  std::ofstream out(argv[1]);
  out << rows.dump(1) << "\n";
  if(!out)
  {
    std::cerr << "export_option_table: cannot write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
