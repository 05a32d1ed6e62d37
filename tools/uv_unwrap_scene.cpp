// uv_unwrap --atlas (uv_unwrap_scene.h).
#include "uv_unwrap_scene.h"

#include "preview/preview.h"
#include "preview/preview_of_mesh.h"
#include "printable_text.h"

#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>

namespace uv_unwrap {

namespace {

using cut_tools::printable_text;
using Mesh = mesh_input::Mesh;
using Point_3 = mesh_input::Point_3;

// --svg with --atlas: every page side by side, each mesh's faces at their UVs
// on their page (tools/preview draws the pages' frames).
void write_scene_svg(const std::string& filename, const Scene& scene, const Scene_packing& packing)
{
  Preview_mesh preview;
  Preview_caption caption;
  caption.pages = packing.pages;
  caption.name = "scene atlas: " + std::to_string(scene.parts.size()) + " meshes, " + std::to_string(packing.pages) +
                 (packing.pages == 1 ? " page" : " pages");
  caption.seconds = -1.;
  double covered = 0.;
  long long crossings = 0;
  for(const Scene_page& page : packing.page)
  {
    covered += page.uv_coverage;
    crossings += static_cast<long long>(page.border_crossings);
  }
  caption.coverage = covered / std::max(packing.pages, 1);
  caption.border_crossings = crossings;
  for(const Scene_part& part : scene.parts)
  {
    const Mesh& mesh = *part.mesh;
    append_to_preview(preview, mesh, part.uvmap, part.seams, preview_page_offset * part.page);
    caption.faces += num_faces(mesh);
  }
  if(!write_uv_svg(filename, preview, caption))
    throw Failure("cannot write '" + filename + "'", "ERROR_CANNOT_WRITE");
}

} // namespace

int run_scene(const Options& options, const std::vector<std::string>& inputs, std::ostream* jsonl,
              const Unwrap_input& unwrap_one, const volatile std::sig_atomic_t& interrupted)
{
  Scene scene;
  std::vector<Run_summary> summaries;
  for(std::size_t i = 0; i < inputs.size() && !interrupted; ++i)
  {
    scene.input = i;
    summaries.push_back(unwrap_one(inputs[i], &scene));
    if(summaries.back().status != "ok") // its primitives unwrapped before the failure stay out
      scene.parts.erase(std::remove_if(scene.parts.begin(), scene.parts.end(),
                                       [i](const Scene_part& p) { return p.input == i; }),
                        scene.parts.end());
  }
  auto fail_all = [&](const Failure& e) {
    for(Run_summary& s : summaries)
      if(s.status == "ok") { s.status = e.status; s.error = e.what(); }
  };
  if(interrupted) fail_all(Failure("interrupted", "ERROR_CANCELED"));
  Scene_packing packing;
  try
  {
    if(!interrupted) packing = pack_scene(scene.parts, options.method);
  }
  catch(const Failure& e)
  {
    fail_all(e);
  }
  for(const auto& [i, write] : scene.writers)
  {
    Run_summary& s = summaries[i];
    if(s.status != "ok") continue;
    try
    {
      write(s);
      s.atlas = atlas_statistics(scene.parts, i, packing);
      // the input's own measures, on its atlas UVs
      s.flipped_faces = s.border_crossings = 0;
      s.overlap_area = s.result.uv_coverage = 0.;
      s.uv_in_unit_square = true;
      for(const Scene_part& p : scene.parts)
        if(p.input == i)
        {
          s.flipped_faces += SMP::number_of_flipped_faces(*p.mesh, p.uvmap);
          s.border_crossings += SMP::number_of_border_crossings(*p.mesh, p.uvmap);
          s.overlap_area += SMP::uv_overlap_area(*p.mesh, p.uvmap);
          s.result.uv_coverage += SMP::uv_area(*p.mesh, p.uvmap);
          s.result.number_of_charts += p.added_charts; // cut for packing
          s.result.seam_length += p.added_seam_length;
          s.uv_in_unit_square = s.uv_in_unit_square && packing.page[std::size_t(p.page)].uv_in_unit_square;
        }
      s.result.uv_scale = packing.texels_per_unit / options.method.texture_size; // UV units per unit of length
    }
    catch(const Failure& e)
    {
      s.status = e.status;
      s.error = e.what();
    }
  }
  int failures = 0;
  for(Run_summary& s : summaries)
  {
    if(s.status != "ok")
    {
      ++failures;
      const bool named = s.error.find(s.input) != std::string::npos;
      std::cerr << "uv_unwrap: error: " << printable_text((named ? std::string() : s.input + ": ") + s.error)
                << std::endl;
    }
    if(jsonl) *jsonl << statistics_text(s) << std::endl;
  }
  if(!options.stats.empty() && !summaries.empty())
  {
    std::ofstream out(options.stats);
    out << statistics_text(summaries.front(), 2) << '\n';
    if(!out) throw Failure("cannot write '" + options.stats + "'", "ERROR_CANNOT_WRITE");
  }
  if(!options.svg.empty() && packing.pages > 0) write_scene_svg(options.svg, scene, packing);
  if(!options.quiet && packing.pages > 0)
  {
    std::cout << "uv_unwrap: atlas of " << scene.parts.size() << " meshes on " << packing.pages
              << (packing.pages == 1 ? " page" : " pages") << ", " << packing.texels_per_unit
              << " texels per unit, " << packing.charts << " charts packed";
    const auto stacked = std::count_if(scene.parts.begin(), scene.parts.end(),
                                       [](const Scene_part& p) { return p.stacked_on >= 0; });
    if(stacked > 0) std::cout << " (" << stacked << " meshes stacked on others: their texels shared)";
    std::cout << "\n";
    for(std::size_t k = 0; k < packing.page.size(); ++k)
    {
      const Scene_page& p = packing.page[k];
      std::cout << "  page " << k << ": " << p.meshes << " meshes, coverage " << 100. * p.uv_coverage
                << " %, flipped faces " << p.flipped_faces << ", border crossings " << p.border_crossings
                << ", overlap area " << p.overlap_area << "\n";
    }
    for(const Run_summary& s : summaries)
      if(s.status == "ok") std::cout << "  wrote " << printable_text(s.output) << "\n";
    std::cout << std::flush;
  }
  return failures;
}


} // namespace uv_unwrap
