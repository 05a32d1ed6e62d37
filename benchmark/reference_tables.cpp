#include "reference_tables.h"

#include "text_parsing.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>

namespace cut_benchmark {

bool read_csv(const fs::path& file, std::vector<Csv_row>& rows)
{
  std::ifstream in(file);
  if(!in) return false;
  auto fields_of = [](const std::string& line) {
    std::vector<std::string> fields;
    std::string cur;
    bool quoted = false;
    for(std::size_t i = 0; i < line.size(); ++i)
    {
      const char c = line[i];
      if(quoted)
      {
        if(c == '"' && i + 1 < line.size() && line[i + 1] == '"') { cur += '"'; ++i; }
        else if(c == '"') quoted = false;
        else cur += c;
      }
      else if(c == '"') quoted = true;
      else if(c == ',') { fields.push_back(trim(cur)); cur.clear(); }
      else cur += c;
    }
    fields.push_back(trim(cur));
    return fields;
  };
  std::vector<std::string> header;
  std::string line;
  while(std::getline(in, line))
  {
    const std::string t = trim(line);
    if(t.empty() || t[0] == '#') continue;
    const auto fields = fields_of(t);
    if(header.empty()) { header = fields; continue; }
    Csv_row row;
    for(std::size_t i = 0; i < header.size(); ++i)
      row[header[i]] = i < fields.size() ? fields[i] : std::string();
    rows.push_back(std::move(row));
  }
  return true;
}

namespace {

double number_in(const Csv_row& row, const std::string& column)
{
  const auto it = row.find(column);
  double x;
  if(it == row.end() || !parse_double(it->second, x)) return NaN;
  return x;
}

std::string text_in(const Csv_row& row, const std::string& column)
{
  const auto it = row.find(column);
  return it == row.end() ? std::string() : it->second;
}

/// The time, E_d and E_s of a row, from the columns so named.
Reference_figures figures_in(const Csv_row& row, const std::string& time, const std::string& distortion = "E_d",
                             const std::string& seam_length = "E_s")
{
  Reference_figures r;
  r.time = number_in(row, time);
  r.distortion = number_in(row, distortion);
  r.seam_length = number_in(row, seam_length);
  return r;
}

} // namespace

std::string stem_of(const std::string& name)
{
  std::string base = fs::path(name).filename().string();
  const auto dot = base.rfind('.');
  if(dot != std::string::npos)
  {
    std::string ext = base.substr(dot + 1);
    for(auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    for(const char* known : {"obj", "off", "ply", "stl", "vtp", "ts"})
      if(ext == known) return base.substr(0, dot);
  }
  return base;
}

References read_references(const fs::path& dir)
{
  References refs;
  std::vector<Csv_row> rows;
  const fs::path measured = dir / "uvat_reference_measured.csv";
  if(!read_csv(measured, rows))
    std::cerr << "warning: cannot read " << measured.string() << "\n";
  for(const auto& row : rows)
  {
    const std::string name = text_in(row, "mesh");
    if(name.empty()) continue;
    Reference_figures r = figures_in(row, "median_time_s");
    r.status = text_in(row, "status");
    if(!refs.measured.count(name)) refs.measured_order.push_back(name);
    refs.measured[name] = r;
  }

  rows.clear();
  const fs::path paper = dir / "paper_table1.csv";
  if(!read_csv(paper, rows))
    std::cerr << "warning: cannot read " << paper.string() << "\n";
  for(const auto& row : rows)
  {
    const std::string file = text_in(row, "mesh_file");
    const std::string model = text_in(row, "model");
    if(file.empty()) { refs.paper_without_file.push_back(model); continue; }
    Reference_figures r = figures_in(row, "at_time_s", "at_distortion", "at_cut_length");
    r.model = model;
    const std::string stem = stem_of(file);
    if(!refs.paper.count(stem)) refs.paper_files.push_back(file);
    refs.paper[stem] = r;
  }
  return refs;
}

bool read_baseline(const fs::path& file, std::map<std::string, Reference_figures>& baseline)
{
  std::vector<Csv_row> rows;
  if(!read_csv(file, rows)) return false;
  for(const auto& row : rows)
  {
    const std::string name = text_in(row, "mesh");
    if(name.empty()) continue;
    baseline[name] = figures_in(row, "time_s");
    baseline[name].status = text_in(row, "status");
  }
  return true;
}

bool read_frontier(const fs::path& file, std::map<std::string, std::vector<Frontier_point>>& frontier)
{
  std::vector<Csv_row> rows;
  if(!read_csv(file, rows)) return false;
  for(const auto& row : rows)
  {
    const std::string name = text_in(row, "mesh");
    const double distortion = number_in(row, "E_d"), seam_length = number_in(row, "E_s");
    if(!name.empty() && !std::isnan(distortion) && !std::isnan(seam_length))
      frontier[name].emplace_back(distortion, seam_length);
  }
  return true;
}

std::vector<Optcuts_figures> read_optcuts_figures(const fs::path& dir)
{
  std::vector<Optcuts_figures> table;
  std::vector<Csv_row> rows;
  const fs::path file = dir / "optcuts_equal_distortion.csv";
  if(!read_csv(file, rows))
    std::cerr << "warning: cannot read " << file.string() << "\n";
  for(const auto& row : rows)
  {
    Optcuts_figures f;
    f.mesh = text_in(row, "mesh");
    if(f.mesh.empty()) continue;
    f.bound = number_in(row, "bound");
    f.reached = figures_in(row, "time_s");
    table.push_back(std::move(f));
  }
  return table;
}

} // namespace cut_benchmark
