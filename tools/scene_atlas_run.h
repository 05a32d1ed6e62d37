// One atlas for a whole scene (uv_unwrap --atlas, uv_unwrap.unwrap_scene()):
// the meshes, unwrapped one by one as without it, handed here as parts (a
// mesh file is one part, each triangle primitive of a glTF one part); all
// their charts are packed by pack_scene_atlas() into pages of one size at
// one texel density; then every page's combined UVs (all the meshes on it
// as one mesh) are measured: flipped faces, border crossings and overlap
// across meshes, coverage. With a stacking tolerance, a mesh that is a rigid
// copy of an earlier one is not unwrapped: it is stacked on it
// (stacked_original()) and gets its UVs and seams from the packing.
#ifndef CUT_PARAM_TOOLS_SCENE_ATLAS_RUN_H
#define CUT_PARAM_TOOLS_SCENE_ATLAS_RUN_H

#include "mesh_input.h"
#include "unwrap_run.h"

#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace uv_unwrap {

/// One mesh of the scene, unwrapped (its seams and UVs as
/// cut_and_parameterize() left them), and how its atlas UVs reach its file.
struct Scene_part
{
  using Mesh = mesh_input::Mesh;
  using Seam_map = Mesh::Property_map<Mesh::Edge_index, bool>;
  using UV_map = Mesh::Property_map<Mesh::Halfedge_index, mesh_input::Kernel::Point_2>;
  std::size_t input = 0;            // the input (file) it belongs to
  std::string name;                 // for messages: the file, or "file, mesh i, primitive j"
  std::shared_ptr<Mesh> mesh;       // shared with the input's writer
  Seam_map seams;
  UV_map uvmap;                     // replaced by the atlas UVs
  std::function<void()> write_back; // after packing: the UVs into the input's document (glTF); may be empty
  int page = -1;                    // set by pack_scene()
  int stacked_on = -1;              // the earlier part whose texels it shares (stacked_original()); -1: its own
  SMP::Cut_and_parameterize_result result; // its unwrapping's (its original's for a stacked copy)
  std::size_t added_charts = 0;     // set by pack_scene(): charts added by cutting for packing
  double added_seam_length = 0.;    // ... and the 3D length of their seams
};

/// The parts of all the inputs, and the writer of each input (called once
/// the atlas is packed), as uv_unwrap --atlas gathers them.
struct Scene
{
  std::vector<Scene_part> parts;
  std::size_t input = 0; // the input being read
  std::vector<std::pair<std::size_t, std::function<void(Run_summary&)>>> writers; // input, its writer
};

/// The measures of one page, taken on the combined UVs of all its meshes.
struct Scene_page
{
  std::size_t meshes = 0, faces = 0, flipped_faces = 0, border_crossings = 0;
  double overlap_area = 0.; // UV area covered more than once, across meshes too
  double uv_coverage = 0.;  // UV area / page area
  bool uv_in_unit_square = true;
};

/// What pack_scene() did.
struct Scene_packing
{
  int pages = 0;
  double texels_per_unit = 0.;
  std::size_t charts = 0;       // charts packed (a stacked copy's are its original's)
  std::vector<Scene_page> page; // one per page
};

/// The index of the part of `parts` that `mesh` is a copy of: the first
/// part, not stacked itself, with the same faces over the same vertex
/// numbering that a rotation and a translation (no mirror) move onto `mesh`
/// within `tolerance` times its bounding box diagonal (find_stacked_meshes());
/// -1 if none or without a tolerance.
/// \pre `tolerance`, if given, is >= 0 and finite (the option table's range)
inline int stacked_original(const std::vector<Scene_part>& parts, const mesh_input::Mesh& mesh,
                            std::optional<double> tolerance)
{
  if(!tolerance) return -1;
  for(std::size_t j = 0; j < parts.size(); ++j)
  {
    const Scene_part& p = parts[j];
    if(p.stacked_on >= 0 || num_vertices(*p.mesh) != num_vertices(mesh) || num_faces(*p.mesh) != num_faces(mesh))
      continue; // the sizes first: most pairs differ there
    std::vector<int> found;
    const std::vector<const mesh_input::Mesh*> pair{p.mesh.get(), &mesh};
    if(SMP::find_stacked_meshes(pair, found, SMP::parameters::stacking_tolerance(*tolerance)) == SMP::OK &&
       found[1] == 0)
      return int(j);
  }
  return -1;
}

/// The summary of a mesh stacked on `original`, which it is not unwrapped
/// for: the original's result (charts, seams, distortion), no time spent.
inline void take_stacked_result(const Scene_part& original, Run_summary& summary)
{
  summary.result = original.result;
  summary.result.timings = SMP::Cut_and_parameterize_timings();
  summary.result.newton_iterations = 0;
  summary.result.number_of_factorizations = summary.result.number_of_solves = 0;
  summary.flipped_faces = summary.border_crossings = 0;
  summary.overlap_area = 0.;
  summary.uv_in_unit_square = true;
  summary.time_seconds = 0.;
}

/// The parts of `page` that have texels of their own (stacked copies left
/// out: they lie on their original's) as one mesh (a disjoint union, UVs carried along).
inline mesh_input::Mesh combined_page(const std::vector<Scene_part>& parts, int page)
{
  mesh_input::Mesh combined;
  bool first = true;
  for(const Scene_part& p : parts)
  {
    if(p.page != page || p.stacked_on >= 0) continue;
    if(first) combined = *p.mesh; // the "h:uv" property comes along
    else combined += *p.mesh;     // join(): properties of the same name are copied too
    first = false;
  }
  return combined;
}

/// Packs every part into one atlas (more pages if `options.texels_per_unit`
/// asks for more texels than one page holds), then measures each page on
/// the parts with texels of their own. A stacked part (`stacked_on` >= 0)
/// gets the UVs and seams of its original, whose page it shares.
/// Throws Failure with the library's error name when packing fails.
/// \pre every `stacked_on` is -1 or the index of an earlier part that is not stacked itself
inline Scene_packing pack_scene(std::vector<Scene_part>& parts, const SMP::Cut_parameterization_options& options)
{
  using Atlas_mesh = SMP::Scene_atlas_mesh<Scene_part::Mesh, Scene_part::Seam_map, Scene_part::UV_map>;
  std::vector<Atlas_mesh> meshes;
  std::vector<int> instance_of;
  for(const Scene_part& p : parts)
  {
    meshes.push_back(SMP::make_scene_atlas_mesh(*p.mesh, p.seams, p.uvmap));
    instance_of.push_back(p.stacked_on);
  }
  if(meshes.empty()) throw Failure("no mesh was unwrapped: no atlas to pack", "ERROR_EMPTY_MESH");
  namespace P = SMP::parameters;
  const SMP::Scene_atlas_result r = SMP::pack_scene_atlas(
    meshes, P::texture_size(options.texture_size,
            P::padding(options.padding,
            P::texels_per_unit(options.texels_per_unit,
            P::instance_of(instance_of,
            P::split_charts_for_packing(options.split_charts_for_packing))))));
  if(r.error != SMP::OK)
    throw Failure(std::string("packing the scene atlas failed: ") + SMP::error_message(r.error) + " (" +
                    SMP::error_name(r.error) + ")" +
                    (r.error == SMP::ERROR_WRONG_PARAMETER && options.texels_per_unit > 0.
                       ? ": a mesh whose charts do not fit one page at the texel density given (lower it, or "
                         "raise the page size: --texels-per-unit, --atlas-size)"
                       : ""),
                  SMP::error_name(r.error));
  Scene_packing packing;
  packing.pages = r.number_of_pages;
  packing.texels_per_unit = r.texels_per_unit;
  packing.charts = r.number_of_charts;
  for(std::size_t m = 0; m < parts.size(); ++m)
  {
    parts[m].page = r.page[m];
    parts[m].added_charts = r.added_charts[m]; // the cuts of split_charts_for_packing
    parts[m].added_seam_length = r.added_seam_length[m];
  }
  for(int page = 0; page < r.number_of_pages; ++page)
  {
    Scene_page s;
    for(const Scene_part& p : parts) s.meshes += p.page == page;
    if(s.meshes == 0) { packing.page.push_back(s); continue; } // (an original is on every page that has a mesh)
    const mesh_input::Mesh combined = combined_page(parts, page);
    const auto uv = combined.property_map<Scene_part::Mesh::Halfedge_index, mesh_input::Kernel::Point_2>("h:uv").first;
    s.faces = num_faces(combined);
    s.flipped_faces = SMP::number_of_flipped_faces(combined, uv);
    s.border_crossings = SMP::number_of_border_crossings(combined, uv);
    s.overlap_area = SMP::uv_overlap_area(combined, uv, std::size_t(std::max(options.texture_size, 1024)));
    s.uv_coverage = SMP::uv_area(combined, uv);
    for(auto h : halfedges(combined))
      if(!is_border(h, combined))
      {
        const auto& q = get(uv, h);
        if(!(q.x() >= 0. && q.x() <= 1. && q.y() >= 0. && q.y() <= 1.)) s.uv_in_unit_square = false;
      }
    packing.page.push_back(s);
  }
  for(Scene_part& p : parts)
    if(p.write_back) p.write_back();
  return packing;
}

/// The "atlas" object of an input's statistics: the page of each of its
/// meshes (one for a mesh file, one per primitive of a glTF), the mesh each
/// is stacked on (its name; null: texels of its own), the density, the
/// charts packed, and the measures of the pages they lie on.
inline nlohmann::ordered_json atlas_statistics(const std::vector<Scene_part>& parts, std::size_t input,
                                               const Scene_packing& packing)
{
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); };
  nlohmann::ordered_json j;
  j["pages"] = nlohmann::ordered_json::array();
  for(const Scene_part& p : parts)
    if(p.input == input) j["pages"].push_back(p.page);
  j["stacked_on"] = nlohmann::ordered_json::array();
  for(const Scene_part& p : parts)
    if(p.input == input)
      j["stacked_on"].push_back(p.stacked_on < 0 ? nlohmann::ordered_json()
                                                 : nlohmann::ordered_json(cut_tools::printable_text(
                                                     parts[std::size_t(p.stacked_on)].name)));
  j["page_count"] = packing.pages;
  j["texels_per_unit"] = number(packing.texels_per_unit);
  j["charts_packed"] = packing.charts;
  std::size_t added_charts = 0;
  double added_seam_length = 0.;
  for(const Scene_part& p : parts)
    if(p.input == input) { added_charts += p.added_charts; added_seam_length += p.added_seam_length; }
  j["charts_added_for_packing"] = added_charts; // split_charts_for_packing's cuts, counted in the input's
  j["seam_length_added_for_packing"] = number(added_seam_length); // number_of_charts and seam_length
  j["page_measures"] = nlohmann::ordered_json::array();
  for(std::size_t k = 0; k < packing.page.size(); ++k)
  {
    const Scene_page& s = packing.page[k];
    j["page_measures"].push_back({{"page", k}, {"meshes", s.meshes}, {"faces", s.faces},
                                  {"flipped_faces", s.flipped_faces}, {"border_crossings", s.border_crossings},
                                  {"overlap_area", number(s.overlap_area)}, {"uv_coverage", number(s.uv_coverage)},
                                  {"uv_in_unit_square", s.uv_in_unit_square}});
  }
  return j;
}

} // namespace uv_unwrap

#endif
