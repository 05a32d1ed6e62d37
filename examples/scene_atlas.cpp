// A scene atlas: several meshes unwrapped one by one, then all their charts
// packed into one shared texture at one texel density (texels per unit of 3D
// length), as a lightmap of a scene needs. First the largest density that
// fits one page, then 1.15 times that density, which needs two pages. Two
// turned and moved copies of the first mesh (a repeated prop) are found by
// find_stacked_meshes(), not unwrapped, and share its texels (stacked parts).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>
#include <CGAL/Aff_transformation_3.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Seam_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using UV_map = Mesh::Property_map<Mesh::Halfedge_index, Point_2>;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) files.push_back(argv[i]);
  if(files.empty())
    for(const char* name : {"meshes/cactus.off", "meshes/joint.off", "meshes/eight.off"})
      files.push_back(CGAL::data_file_path(name));

  // the meshes, then two copies of the first one, turned about z and moved
  const std::size_t originals = files.size();
  std::vector<Mesh> meshes(originals + 2);
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const std::string& file = files[m < originals ? m : 0];
    if(!CGAL::IO::read_polygon_mesh(file, meshes[m]) || !CGAL::is_triangle_mesh(meshes[m]))
    {
      std::cerr << "Cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    if(m < originals) continue;
    const double angle = m == originals ? 1. : 2.5, c = std::cos(angle), s = std::sin(angle);
    const CGAL::Aff_transformation_3<Kernel> motion(c, -s, 0., 10. * m, s, c, 0., 0., 0., 0., 1., 0.);
    for(auto v : vertices(meshes[m])) meshes[m].point(v) = motion(meshes[m].point(v));
  }
  std::vector<const Mesh*> pointers;
  for(const Mesh& mesh : meshes) pointers.push_back(&mesh);
  std::vector<int> stacked_on;
  if(SMP::find_stacked_meshes(pointers, stacked_on, SMP::parameters::stacking_tolerance(1e-4)) != SMP::OK)
    return EXIT_FAILURE;

  // each original unwrapped on its own (its own seams and charts); the copies are not
  std::vector<SMP::Scene_atlas_mesh<Mesh, Seam_map, UV_map>> scene;
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    Seam_map seams = meshes[m].add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
    UV_map uvmap = meshes[m].add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
    scene.push_back(SMP::make_scene_atlas_mesh(meshes[m], seams, uvmap));
    if(stacked_on[m] != int(m))
    {
      std::cout << "mesh " << m << ": a copy of mesh " << stacked_on[m] << ", not unwrapped\n";
      continue;
    }
    const auto unwrapped = SMP::cut_and_parameterize(meshes[m], seams, uvmap);
    if(!unwrapped.ok())
    {
      std::cerr << files[m] << ": " << SMP::error_message(unwrapped.error) << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << files[m] << ": " << num_faces(meshes[m]) << " faces, " << unwrapped.number_of_charts << " charts\n";
  }

  // one 512 x 512 page, 4 texels between charts: the largest common density
  const auto one_page = SMP::pack_scene_atlas(
    scene, SMP::parameters::instance_of(stacked_on, SMP::parameters::texture_size(512, SMP::parameters::padding(4.))));
  if(one_page.error != SMP::OK)
  {
    std::cerr << "Failed: " << SMP::error_message(one_page.error) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "one page: " << one_page.texels_per_unit << " texels per unit, " << one_page.number_of_charts
            << " charts packed\n";
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const std::string output = "scene_atlas_" + std::to_string(m) + ".obj";
    if(!SMP::write_OBJ_with_uvs(output, meshes[m], scene[m].uvmap))
    {
      std::cerr << "Cannot write " << output << std::endl;
      return EXIT_FAILURE;
    }
  }

  // 1.15 times the density (1.3 times the area): the meshes no longer fit one page (each still
  // fits one: the largest density may have turned charts to free angles, pages do not)
  const auto pages = SMP::pack_scene_atlas(
    scene, SMP::parameters::instance_of(
             stacked_on, SMP::parameters::texels_per_unit(
                           1.15 * one_page.texels_per_unit, SMP::parameters::texture_size(512, SMP::parameters::padding(4.)))));
  if(pages.error != SMP::OK)
  {
    std::cerr << "Failed: " << SMP::error_message(pages.error) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "at " << pages.texels_per_unit << " texels per unit: " << pages.number_of_pages << " pages\n";
  for(std::size_t m = 0; m < meshes.size(); ++m) std::cout << "  mesh " << m << ": page " << pages.page[m] << "\n";

  // the copies not stacked: given the first mesh's UVs and seams (the same
  // halfedges, read from the same file), they are packed three times
  for(std::size_t m = originals; m < meshes.size(); ++m)
  {
    for(auto h : halfedges(meshes[m])) put(scene[m].uvmap, h, get(scene[0].uvmap, h));
    for(auto e : edges(meshes[m])) put(scene[m].seam_edge_map, e, get(scene[0].seam_edge_map, e));
  }
  const auto unstacked = SMP::pack_scene_atlas(scene, SMP::parameters::texture_size(512, SMP::parameters::padding(4.)));
  std::cout << "without stacking: " << unstacked.texels_per_unit << " texels per unit, " << unstacked.number_of_charts
            << " charts packed\n";
  // (the density is a packing heuristic's: fewer charts need not pack denser)
  const bool stacked = stacked_on[originals] == 0 && stacked_on[originals + 1] == 0 &&
                       unstacked.number_of_charts > one_page.number_of_charts;
  return pages.number_of_pages > 1 && stacked ? EXIT_SUCCESS : EXIT_FAILURE;
}
