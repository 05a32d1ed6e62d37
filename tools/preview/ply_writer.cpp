#include "preview_detail.h"

#include <cmath>
#include <cstdio>
#include <memory>

bool write_v_field_ply(const std::string& path, const Preview_mesh& mesh)
{
  using namespace uv_preview_detail;
  if(!valid_mesh(mesh, false) || mesh.face_v.size() != mesh.faces.size())
    return false;
  for(double v : mesh.face_v)
    if(!std::isfinite(v))
      return false;

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if(!file)
    return false;
  std::FILE* f = file.get();
  // Face colors as face properties: MeshLab, Blender and CloudCompare read
  // red/green/blue on the face element as per-face color.
  std::fprintf(f,
               "ply\nformat ascii 1.0\n"
               "comment v: discontinuity field, 0 = cut wanted, 1 = kept (threshold 0.5)\n"
               "element vertex %zu\n"
               "property float x\nproperty float y\nproperty float z\n"
               "element face %zu\n"
               "property list uchar int vertex_indices\n"
               "property uchar red\nproperty uchar green\nproperty uchar blue\n"
               "property float v\n"
               "end_header\n",
               mesh.points.size(), mesh.faces.size());
  for(const auto& p : mesh.points)
    std::fprintf(f, "%.8g %.8g %.8g\n", p[0], p[1], p[2]);
  for(std::size_t i = 0; i < mesh.faces.size(); ++i)
  {
    const auto& t = mesh.faces[i];
    const Rgb c = v_field_color(mesh.face_v[i]);
    std::fprintf(f, "3 %d %d %d %u %u %u %.6g\n", t[0], t[1], t[2], unsigned(c[0]), unsigned(c[1]),
                 unsigned(c[2]), mesh.face_v[i]);
  }
  // fclose reports deferred write errors (e.g. a full disk).
  return std::ferror(f) == 0 && std::fclose(file.release()) == 0;
}
