// Internals shared by the preview writers (and the test, which checks
// colors). Not part of the API used by uv_unwrap.
#ifndef UV_PREVIEW_PREVIEW_DETAIL_H
#define UV_PREVIEW_PREVIEW_DETAIL_H

#include "preview.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace uv_preview_detail {

using Rgb = std::array<unsigned char, 3>;

// Seams: orange-red, absent from both the viridis ramp and the checker.
constexpr Rgb seam_rgb{255, 64, 0};
// Flipped UV triangles: magenta, also absent from the ramp.
constexpr Rgb flipped_rgb{255, 0, 255};
// Faces without a distortion value.
constexpr Rgb no_data_rgb{190, 190, 190};

// Viridis-like perceptual ramp, t in [0,1] (clamped).
Rgb viridis(double t);
// Diverging red (0) -> pale yellow (0.5) -> blue (1) ramp for the v field,
// centered on the 0.5 cut threshold.
Rgb v_field_color(double v);

std::string hex(const Rgb& c);

// Checks what every writer needs: faces, indices in range, finite points,
// optional arrays either empty or one entry per face. With need_uv, also
// corner_uv present and finite.
bool valid_mesh(const Preview_mesh& mesh, bool need_uv);

// Twice the signed area of face f in UV (positive: counter-clockwise).
double uv_signed_area2(const Preview_mesh& mesh, std::size_t f);

struct Box2
{
  double lo[2], hi[2];
};
Box2 uv_bounds(const Preview_mesh& mesh);

// Edges of the UV layout that bound a chart: (face, local edge k from corner
// k to corner k+1) whose corner pair (vertices and their UVs) is used by no
// other face. Exact UV copies across a non-seam edge are what makes two
// occurrences match, so a tiny tolerance relative to the layout size is used.
std::vector<std::pair<std::size_t, int>> uv_boundary_edges(const Preview_mesh& mesh);

// Key of an undirected vertex pair, for seam look-ups.
inline std::uint64_t edge_key(int a, int b)
{
  if(a > b)
    std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

} // namespace uv_preview_detail

#endif // UV_PREVIEW_PREVIEW_DETAIL_H
