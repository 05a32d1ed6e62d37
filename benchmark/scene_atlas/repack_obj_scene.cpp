// Packs again, with pack_scene_atlas(), the scene atlas of OBJ files that
// already hold one UV map each (e.g. the outputs of uv_unwrap --atlas): the
// charts are the faces joined across edges whose two sides share their vt;
// prints the charts, the density, the seams added by
// --split-charts-for-packing, the coverage and the combined UVs' flips,
// crossings and overlap (one page), and writes the merged OBJ if asked.
// Measures the packing alone, without unwrapping the meshes again.
//   repack_obj_scene SIZE PADDING FILL(0: off) MERGED.obj|- A.obj B.obj ...
// Not built by CMake; from the repository root:
//   g++ -O2 -DNDEBUG -frounding-math -std=gnu++17 -DCGAL_EIGEN3_ENABLED -Iinclude -isystem /usr/include/eigen3 \
//     benchmark/scene_atlas/repack_obj_scene.cpp -o repack_obj_scene -lgmp -lmpfr
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Point_2 = Kernel::Point_2;
namespace SMP = CGAL::Surface_mesh_parameterization;

struct Part
{
  Mesh mesh;
  Mesh::Property_map<Mesh::Halfedge_index, Point_2> uv;
  Mesh::Property_map<Mesh::Edge_index, bool> seam;
};

static bool read_obj(const std::string& path, Part& part)
{
  std::ifstream in(path);
  std::vector<Point_2> vt;
  std::vector<Mesh::Vertex_index> v;
  std::string line;
  std::vector<std::pair<std::array<Mesh::Vertex_index, 3>, std::array<int, 3>>> faces;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v") { double x, y, z; s >> x >> y >> z; v.push_back(part.mesh.add_vertex(Kernel::Point_3(x, y, z))); }
    else if(tag == "vt") { double x, y; s >> x >> y; vt.emplace_back(x, y); }
    else if(tag == "f")
    {
      std::array<Mesh::Vertex_index, 3> f;
      std::array<int, 3> t{-1, -1, -1};
      for(int k = 0; k < 3; ++k)
      {
        std::string c;
        s >> c;
        const std::size_t slash = c.find('/');
        f[k] = v[std::size_t(std::stoi(c.substr(0, slash)) - 1)];
        if(slash != std::string::npos) t[k] = std::stoi(c.substr(slash + 1)) - 1;
      }
      faces.push_back({f, t});
    }
  }
  part.uv = part.mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
  part.seam = part.mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto vt_of = part.mesh.add_property_map<Mesh::Halfedge_index, int>("h:vt", -1).first;
  for(const auto& [f, t] : faces)
  {
    const Mesh::Face_index face = part.mesh.add_face(f[0], f[1], f[2]);
    if(face == Mesh::null_face()) return false;
    Mesh::Halfedge_index h = part.mesh.halfedge(face);
    for(int i = 0; i < 3; ++i, h = part.mesh.next(h))
    {
      const Mesh::Vertex_index target = part.mesh.target(h);
      const int k = target == f[0] ? 0 : (target == f[1] ? 1 : 2);
      vt_of[h] = t[k];
      part.uv[h] = vt.at(std::size_t(t[k]));
    }
  }
  for(Mesh::Edge_index e : part.mesh.edges())
  {
    const Mesh::Halfedge_index h = part.mesh.halfedge(e), o = part.mesh.opposite(h);
    if(part.mesh.is_border(h) || part.mesh.is_border(o)) continue;
    part.seam[e] = vt_of[h] != vt_of[part.mesh.prev(o)] || vt_of[o] != vt_of[part.mesh.prev(h)];
  }
  return true;
}

int main(int argc, char** argv)
{
  if(argc < 6) { std::cerr << "usage: repack_obj_scene SIZE PADDING FILL MERGED.obj|- A.obj ...\n"; return 2; }
  const int size = std::stoi(argv[1]);
  const double padding = std::stod(argv[2]), fill = std::stod(argv[3]);
  const std::string merged = argv[4];
  std::vector<Part> parts(std::size_t(argc - 5));
  for(int i = 5; i < argc; ++i)
    if(!read_obj(argv[i], parts[std::size_t(i - 5)])) { std::cerr << "cannot read " << argv[i] << "\n"; return 1; }
  using Atlas_mesh = SMP::Scene_atlas_mesh<Mesh, decltype(Part::seam), decltype(Part::uv)>;
  std::vector<Atlas_mesh> meshes;
  double seams_before = 0.; // E_s summed over the meshes (3D length / sqrt(3D area / pi) each)
  for(Part& p : parts)
  {
    meshes.push_back(SMP::make_scene_atlas_mesh(p.mesh, p.seam, p.uv));
    double length = 0., area = 0.;
    for(Mesh::Edge_index e : p.mesh.edges())
      if(p.seam[e]) length += std::sqrt(CGAL::squared_distance(p.mesh.point(p.mesh.vertex(e, 0)), p.mesh.point(p.mesh.vertex(e, 1))));
    for(Mesh::Face_index f : p.mesh.faces())
    {
      const Mesh::Halfedge_index h = p.mesh.halfedge(f);
      area += std::sqrt(CGAL::squared_area(p.mesh.point(p.mesh.source(h)), p.mesh.point(p.mesh.target(h)),
                                           p.mesh.point(p.mesh.target(p.mesh.next(h)))));
    }
    seams_before += length / std::sqrt(area / M_PI);
  }
  namespace P = SMP::parameters;
  const auto start = std::chrono::steady_clock::now();
  const SMP::Scene_atlas_result r =
    fill > 0. ? SMP::pack_scene_atlas(meshes, P::texture_size(size, P::padding(padding, P::split_charts_for_packing(fill))))
              : SMP::pack_scene_atlas(meshes, P::texture_size(size, P::padding(padding)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(r.error != SMP::OK) { std::cerr << "packing failed: " << SMP::error_name(r.error) << "\n"; return 1; }
  Mesh all;
  auto all_uv = all.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
  all.add_property_map<Mesh::Edge_index, bool>("e:seam", false);
  std::size_t added = 0;
  double added_length = 0.;
  for(std::size_t m = 0; m < parts.size(); ++m)
  {
    all += parts[m].mesh;
    added += r.added_charts[m];
    added_length += r.added_seam_length[m];
  }
  std::size_t seam_edges_on_border = 0;
  for(const Part& p : parts)
    for(Mesh::Edge_index e : p.mesh.edges())
      seam_edges_on_border += p.seam[e] && p.mesh.is_border(e);
  std::cout.precision(6);
  std::cout << "meshes " << parts.size() << " faces " << all.number_of_faces() << " pages " << r.number_of_pages
            << " charts " << r.number_of_charts << " (added " << added << ") texels_per_unit " << r.texels_per_unit
            << " coverage " << SMP::uv_area(all, all_uv) << " E_s " << seams_before << " -> "
            << seams_before + added_length << " flips " << SMP::number_of_flipped_faces(all, all_uv)
            << " crossings " << SMP::number_of_border_crossings(all, all_uv) << " overlap "
            << SMP::uv_overlap_area(all, all_uv, std::size_t(std::max(size, 1024))) << " seams_on_border "
            << seam_edges_on_border << " pack_s " << seconds << std::endl;
  if(merged != "-")
  {
    std::ofstream out(merged);
    out.precision(17);
    for(Mesh::Vertex_index v : all.vertices()) out << "v " << all.point(v) << "\n";
    for(Mesh::Halfedge_index h : all.halfedges())
      if(!all.is_border(h)) out << "vt " << all_uv[h] << "\n";
    std::map<Mesh::Halfedge_index, std::size_t> index;
    std::size_t n = 0;
    for(Mesh::Halfedge_index h : all.halfedges())
      if(!all.is_border(h)) index[h] = ++n;
    for(Mesh::Face_index f : all.faces())
    {
      out << "f";
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(all.halfedge(f), all))
        out << " " << std::size_t(all.target(h)) + 1 << "/" << index[h];
      out << "\n";
    }
  }
  return 0;
}
