// Generators of the input classes met in models from the wild (issue 43):
// quads folded over a common diagonal, edges shared by four faces, separate
// parts with holes, repeated faces, degenerate faces and pinched vertices in
// a soup that the input path repairs. Each returns a Soup (generators.h);
// most are not valid polygon meshes on purpose, and are meant for the tools'
// input path (written with write_obj()), which repairs them.
#ifndef CUT_PARAM_TEST_WILD_INPUT_GENERATORS_H
#define CUT_PARAM_TEST_WILD_INPUT_GENERATORS_H

#include "generators.h"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace cut_test {

/// Two quads folded over their common diagonal a-c: a, b, c, d around a
/// square, x above its center, quads (a,b,c,x) and (c,d,a,x); x has two
/// faces. Split along a-c (the shorter diagonal, which a Delaunay split
/// picks), both quads would make two edges between a and c: in the soup, an
/// edge of four triangles, as in a famous 500-face quad head. `quads`
/// false: already split so (four triangles, two of them the same triangle
/// reversed).
inline Soup folded_quads_soup(bool quads = true)
{
  Soup s;
  const std::size_t a = s.add_point(0., 0., 0.), b = s.add_point(0.5, -1., 0.), c = s.add_point(1., 0., 0.),
                    d = s.add_point(0.5, 1., 0.), x = s.add_point(0.5, 0., 1.);
  if(quads)
  {
    s.faces.push_back({a, b, c, x});
    s.faces.push_back({c, d, a, x});
  }
  else
  {
    s.add_triangle(a, b, c);
    s.add_triangle(a, c, x);
    s.add_triangle(c, d, a);
    s.add_triangle(c, a, x);
  }
  return s;
}

/// Two n × n grids crossing at right angles along their middle line (the
/// points of that line shared): each edge of the line is shared by four
/// faces. n even.
inline Soup crossing_sheets_soup(int n)
{
  Soup s = grid_soup(n, n, 2., 2.).translate(-1., -1., 0.);
  Soup other = grid_soup(n, n, 2., 2.).translate(-1., -1., 0.);
  other.transform([](const Soup::Point& p) { return Soup::Point{p[0], 0., p[1]}; });
  const std::size_t offset = s.points.size();
  s.points.insert(s.points.end(), other.points.begin(), other.points.end());
  const int middle = n / 2; // the row y = 0 of the first grid, z = 0 of the second
  for(auto f : other.faces)
  {
    for(std::size_t& i : f)
    {
      const int col = int(i % std::size_t(n + 1)), row = int(i / std::size_t(n + 1));
      i = row == middle ? std::size_t(middle * (n + 1) + col) : i + offset;
    }
    s.faces.push_back(f);
  }
  return s.remove_unused_points();
}

/// A sphere (sphere_soup(n), radius r, centered at c) without the faces
/// whose center lies within the angle acos(cos_angle) of a direction of
/// `holes` (unit vectors) seen from its center: one hole per direction.
inline Soup sphere_with_holes_soup(int n, double r, const Soup::Point& c, const std::vector<Soup::Point>& holes,
                                   double cos_angle)
{
  const Soup sphere = sphere_soup(n, 1.);
  Soup s;
  s.points = sphere.points;
  for(const auto& f : sphere.faces)
  {
    Soup::Point m{0., 0., 0.};
    for(std::size_t i : f)
      for(int k = 0; k < 3; ++k) m[k] += sphere.points[i][k] / 3.;
    const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    bool in_hole = false;
    for(const Soup::Point& h : holes)
      in_hole = in_hole || (m[0] * h[0] + m[1] * h[1] + m[2] * h[2]) / len > cos_angle;
    if(!in_hole) s.faces.push_back(f);
  }
  s.remove_unused_points();
  s.scale(r).translate(c[0], c[1], c[2]);
  return s;
}

/// A head: a sphere with two eye holes, and two separate eye parts in them,
/// each a smaller sphere with a hole at its back (three components, none a
/// disk, four border loops), as in quad head models with separate eyes.
inline Soup head_with_eyes_soup(int n = 8)
{
  const double h = 1. / std::sqrt(0.4 * 0.4 + 0.8 * 0.8 + 0.45 * 0.45);
  Soup s = sphere_with_holes_soup(n, 1., {0., 0., 0.}, {{0.4 * h, 0.8 * h, 0.45 * h}, {-0.4 * h, 0.8 * h, 0.45 * h}},
                                  0.93);
  for(double side : {1., -1.})
    s.append(sphere_with_holes_soup(n / 2, 0.2, {side * 0.36, 0.74, 0.41}, {{0., -1., 0.}}, 0.7));
  return s;
}

/// A wavy n × n grid with some faces repeated: `same` in the same
/// orientation, `reversed` reversed, and one repeated with its corners
/// rotated.
inline Soup repeated_faces_soup(int n = 10)
{
  Soup s = grid_soup(n, n);
  s.transform([](const Soup::Point& p) { return Soup::Point{p[0], p[1], 0.3 * p[0] * p[1]}; });
  const std::size_t faces = s.faces.size();
  for(std::size_t f = 5; f < 9; ++f) s.faces.push_back(s.faces[f]);
  for(std::size_t f = 20; f < 24; ++f) s.faces.push_back({s.faces[f][2], s.faces[f][1], s.faces[f][0]});
  s.faces.push_back({s.faces[faces / 2][1], s.faces[faces / 2][2], s.faces[faces / 2][0]});
  return s;
}

/// A soup that the input path repairs, with degenerate faces left: two
/// grids touching at one corner (a vertex joining two fans), a zero-area
/// face along a border edge, a face with a repeated corner, a needle and an
/// inconsistently oriented face.
inline Soup degenerate_soup(int n = 8)
{
  Soup s = grid_soup(n, n);
  Soup other = grid_soup(n, n);
  other.transform([](const Soup::Point& p) { return Soup::Point{1. + p[0], 1. + p[1], 0.5 * p[0]}; });
  const std::size_t corner = std::size_t(n * (n + 1) + n), offset = s.points.size();
  s.points.insert(s.points.end(), other.points.begin(), other.points.end());
  for(auto f : other.faces)
  {
    for(std::size_t& i : f) i = i == 0 ? corner : i + offset;
    s.faces.push_back(f);
  }
  const std::size_t mid = s.add_point(0.5 / n, 0., 0.);   // on the border edge (0,1)
  s.add_triangle(0, 1, mid);                              // zero area, along the border
  s.add_triangle(2, 3, 3);                                // a repeated corner
  const std::size_t tip = s.add_point(1.5 / n, -1e-9, 0.); // a needle on edge (1,2)
  s.add_triangle(2, 1, tip);
  std::swap(s.faces[7][0], s.faces[7][1]);                // flipped
  return s.remove_unused_points();
}

/// A unit square (two triangles) with `pages` thin triangles hung on its
/// diagonal, as a scan or a boolean leaves fins: one edge of pages + 2
/// faces. Each thin triangle has its apex near the diagonal's midpoint, at
/// a height of 1-3% of the diagonal's length, so that the repair leaves it
/// a chart of its own that only a sliver of E_d 4 maps without distortion.
inline Soup sliver_book_soup(int pages = 17)
{
  Soup s;
  const std::size_t a = s.add_point(0., 0., 0.), b = s.add_point(1., 0., 0.), c = s.add_point(1., 1., 0.),
                    d = s.add_point(0., 1., 0.);
  s.add_triangle(a, b, c);
  s.add_triangle(a, c, d);
  for(int i = 0; i < pages; ++i)
  {
    const double angle = 2. * M_PI * (i + 0.5) / pages, height = 0.015 + 0.01 * (i % 3);
    const double t = 0.45 + 0.1 * double(i) / pages; // along the diagonal
    // off the diagonal: in the direction (1, -1, 0) / sqrt 2 and z
    const double off = height * std::cos(angle) / std::sqrt(2.), up = height * std::sin(angle);
    s.add_triangle(a, c, s.add_point(t + off, t - off, up));
  }
  return s;
}

/// Writes `soup` as an OBJ file (vertices and faces, 1-based); false on failure.
inline bool write_obj(const Soup& soup, const std::string& filename)
{
  std::ofstream out(filename);
  out.precision(17);
  for(const auto& p : soup.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const auto& f : soup.faces)
  {
    out << 'f';
    for(std::size_t i : f) out << ' ' << i + 1;
    out << '\n';
  }
  return bool(out);
}

} // namespace cut_test

#endif
