#include "hard_surface.h"

#include "benchmark_run.h"
#include "hard_surface_meshes.h"
#include "scaling.h"

#include <CGAL/boost/graph/IO/OBJ.h>

#include <algorithm>
#include <fstream>
#include <iostream>

namespace cut_benchmark {

namespace {

struct Corpus_mesh
{
  std::string name;
  std::string source; // "generated" or "CGAL"
  Mesh mesh;
};

/// "valid": run, no flipped face, no UV border crossing.
bool is_valid(const Run_result& r) { return r.ok && r.flipped == 0 && r.crossings == 0; }

std::vector<std::string> row(const Corpus_mesh& m, const Run_result& r)
{
  const std::size_t rest = r.newton - std::min(r.newton, r.u_newton + r.final_newton + r.box_newton + r.relax_newton);
  return {m.name, m.source, std::to_string(r.faces), r.ran ? time_text(r.time) : "-", r.status,
          std::to_string(r.newton), std::to_string(r.u_newton), std::to_string(r.final_newton),
          std::to_string(r.box_newton), std::to_string(r.relax_newton), std::to_string(rest),
          std::to_string(r.factorizations), fixed(r.distortion, 4), fixed(r.seam_length, 3), std::to_string(r.charts),
          std::to_string(r.welded), std::to_string(r.flipped), std::to_string(r.crossings), is_valid(r) ? "yes" : "NO"};
}

const std::vector<Column>& columns()
{
  static const std::vector<Column> c{{"mesh", true}, {"source", true}, {"faces"}, {"time (s)"}, {"status", true},
                                     {"Newton"}, {"altern."}, {"final"}, {"box"}, {"relax"}, {"rest"},
                                     {"factor."}, {"E_d"}, {"E_s"}, {"charts"}, {"welded"}, {"flipped"},
                                     {"crossings"}, {"valid", true}};
  return c;
}

} // namespace

int run_hard_surface(const Options& opt)
{
  std::vector<Corpus_mesh> corpus;
  auto wanted = [&](const std::string& name) {
    return opt.meshes.empty() || std::find(opt.meshes.begin(), opt.meshes.end(), name) != opt.meshes.end();
  };
  for(const hard_surface::Generated& g : hard_surface::generated_meshes())
    if(wanted(g.name)) corpus.push_back({g.name, "generated", g.make()});
  for(const std::string& file : hard_surface::cgal_cad_meshes())
  {
    const std::string name = fs::path(file).stem().string();
    if(!wanted(name)) continue;
    const fs::path path = cgal_data_file("meshes/" + file);
    Corpus_mesh m{name, "CGAL", Mesh()};
    if(path.empty() || !CGAL::IO::read_polygon_mesh(path.string(), m.mesh, CGAL::parameters::verbose(false)))
    {
      std::cerr << "note: " << file << " not found in CGAL's data set (set CGAL_DATA_DIR): left out\n";
      continue;
    }
    corpus.push_back(std::move(m));
  }
  if(opt.max_faces)
    corpus.erase(std::remove_if(corpus.begin(), corpus.end(),
                                [&](const Corpus_mesh& m) { return num_faces(m.mesh) > *opt.max_faces; }),
                 corpus.end());
  if(corpus.empty()) { std::cerr << "error: no mesh to run\n"; return 2; }

  if(!opt.write_meshes_dir.empty())
  {
    fs::create_directories(opt.write_meshes_dir);
    for(const Corpus_mesh& m : corpus)
    {
      std::ofstream out(opt.write_meshes_dir / (m.name + ".obj"));
      out.precision(17);
      if(!CGAL::IO::write_OBJ(out, m.mesh)) { std::cerr << "error: cannot write " << m.name << ".obj\n"; return 2; }
    }
    std::cout << "wrote " << corpus.size() << " meshes to " << opt.write_meshes_dir.string() << "\n";
    return 0;
  }

  const auto np = method_parameters(opt, opt.method.distortion_bound);
  std::vector<std::vector<std::string>> cells;
  std::vector<std::pair<double, std::size_t>> by_time;
  std::ofstream csv;
  if(!opt.csv_file.empty())
  {
    csv.open(opt.csv_file);
    csv << "mesh,source,faces,time,status,newton_iterations,alternation_iterations,final_iterations,box_iterations,"
           "relax_iterations,factorizations,E_d,E_s,charts,welded,flipped,crossings,valid\n";
  }
  std::size_t invalid = 0;
  for(std::size_t i = 0; i < corpus.size(); ++i)
  {
    Corpus_mesh& m = corpus[i];
    std::cerr << "[" << i + 1 << "/" << corpus.size() << "] " << m.name << " (" << num_faces(m.mesh) << " faces) ... "
              << std::flush;
    Run_result r;
    r.faces = num_faces(m.mesh);
    try
    {
      run_method(m.mesh, opt.repeat_count(), np, r);
    }
    catch(const std::exception& e)
    {
      r.ok = false;
      r.status = "EXCEPTION";
      r.note = e.what();
    }
    std::cerr << r.status << " (" << time_text(r.time) << " s)\n";
    if(!r.note.empty()) std::cerr << "  note: " << r.note << "\n";
    if(!is_valid(r)) ++invalid;
    cells.push_back(row(m, r));
    by_time.emplace_back(r.time, i);
    if(csv)
      csv << csv_field(m.name) << ',' << m.source << ',' << r.faces << ',' << full(r.time) << ',' << r.status << ','
          << r.newton << ',' << r.u_newton << ',' << r.final_newton << ',' << r.box_newton << ',' << r.relax_newton
          << ',' << r.factorizations << ',' << full(r.distortion) << ',' << full(r.seam_length) << ',' << r.charts
          << ',' << r.welded << ',' << r.flipped << ',' << r.crossings << ',' << (is_valid(r) ? 1 : 0) << '\n';
  }
  std::cout << "Hard-surface corpus (" << parameters_text(opt) << ")\n"
            << "Newton iterations: all; in the alternation's u-steps; final solves without box; box solves;\n"
            << "relaxations judging trial cuts and zips; the rest (first u-steps, rerouted seams)\n";
  print_table(std::cout, columns(), cells);
  std::sort(by_time.begin(), by_time.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::vector<std::string>> slowest;
  for(std::size_t k = 0; k < by_time.size() && k < 10; ++k) slowest.push_back(cells[by_time[k].second]);
  std::cout << "\nThe ten slowest:\n";
  print_table(std::cout, columns(), slowest);
  if(invalid) std::cout << "\n" << invalid << " mesh(es) without a valid atlas\n";
  return invalid ? 1 : 0;
}

} // namespace cut_benchmark
