// Preview images of a UV map: what a person looks at to judge an unwrap.
//
// Deliberately independent of CGAL: the caller copies its result into plain
// arrays, so the writers compile fast and can be fed from any mesh type.
//
// All writers validate their input and return false (writing nothing) on
// bad data: no faces, indices out of range, non-finite coordinates, array
// sizes that do not match, or a file that cannot be written.
#ifndef UV_PREVIEW_PREVIEW_H
#define UV_PREVIEW_PREVIEW_H

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

struct Preview_mesh
{
  // Input (uncut) mesh: 3D positions and triangles.
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 3>> faces;
  // UV of each corner: corner_uv[f][k] belongs to vertex faces[f][k].
  // Corners of one vertex differ across seams. Required (same size as faces).
  std::vector<std::array<std::array<double, 2>, 3>> corner_uv;
  // Seam edges as pairs of indices into points (order irrelevant).
  std::vector<std::pair<int, int>> seam_edges;
  // Per face sigma1^2 + sigma2^2 + sigma1^-2 + sigma2^-2 (4 = isometric).
  // Optional: empty means faces are drawn in a neutral gray.
  std::vector<double> face_distortion;
  // Per face discontinuity field v in [0,1] (optional; needed by the PLY).
  std::vector<double> face_v;
};

struct Preview_caption
{
  double distortion = 0;   // E_d
  double seam_length = 0;  // E_s
  double seconds = 0;      // negative: not shown
  std::size_t faces = 0;
  std::size_t charts = 0;
  std::string name;
  double coverage = -1;            // UV area / texture square area, in [0,1]; negative: not shown
  long long border_crossings = -1; // crossing UV border segments (overlaps); negative: not shown
  int pages = 0;                   // > 0: a scene atlas, page p's UVs moved by p * preview_page_offset in u
};

// The u offset between the pages of a scene atlas drawn side by side (a tenth of a page between them).
constexpr double preview_page_offset = 1.1;

// UV layout fitted to the page: faces filled by distortion (viridis-like ramp
// on a log scale, with a legend), chart outlines, seams on top, a caption.
// Flipped UV triangles (non-positive signed area) are filled in magenta.
// A layout inside the unit square (a texture atlas) is shown in the whole
// square, whose outline is drawn dashed.
bool write_uv_svg(const std::string& path, const Preview_mesh& mesh,
                  const Preview_caption& caption);

// Where the checker preview looks from. Directions are in mesh coordinates
// and need not be unit or exactly perpendicular.
struct Preview_camera
{
  std::array<double, 3> up{0, 1, 0};    // shown pointing up on screen
  std::array<double, 3> front{0, 0, 1}; // side of the mesh the first view faces
  double azimuth = 30;                  // degrees, turning from front around up
  double elevation = 20;                // degrees above the horizontal plane
};

// Camera for a mesh whose up axis is "x", "y", "z", "+z", "-y", ... (case
// insensitive). Front is +z for x- or y-up meshes and -y for z-up meshes
// (the usual z-up convention: the front view looks along +y).
// Returns false, leaving `camera` alone, for any other text.
bool preview_camera_for_up_axis(const std::string& axis, Preview_camera& camera);

// Software-rendered view(s) of the 3D mesh with a checkerboard texture mapped
// through corner_uv, Lambert-shaded with a headlight, seams drawn on top.
// With two_views, the image holds the camera's view and the view from the
// opposite side, side by side. Without a camera the mesh is taken as y-up
// (the OBJ convention).
bool write_checker_png(const std::string& path, const Preview_mesh& mesh,
                       int width = 1024, int height = 768, bool two_views = true);
bool write_checker_png(const std::string& path, const Preview_mesh& mesh,
                       int width, int height, bool two_views, const Preview_camera& camera);

// The render of write_checker_png() with each face colored by face_v
// instead of the checker (the colors of write_v_field_ply(): red where v = 0,
// a cut wants to go there; pale at 0.5; blue at 1) and the seams in black.
// Requires face_v.size() == faces.size(), every value finite.
bool write_v_field_png(const std::string& path, const Preview_mesh& mesh, int width, int height, bool two_views,
                       const Preview_camera& camera);
// ASCII PLY of the mesh with per-face colors from face_v (red: v=0, a cut
// wants to go there; pale at the 0.5 threshold; blue: v=1) and a per-face
// float property "v". Requires face_v.size() == faces.size().
bool write_v_field_ply(const std::string& path, const Preview_mesh& mesh);

#endif // UV_PREVIEW_PREVIEW_H
