#include "preview_detail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <unordered_set>

namespace {

using namespace uv_preview_detail;

// Up to two decimals, no trailing zeros: at page scale 0.01 unit is far
// below a pixel, and shared corners round identically so no cracks appear.
void put_num(std::string& out, double x)
{
  long long i = std::llround(x * 100);
  if(i < 0)
  {
    out += '-';
    i = -i;
  }
  out += std::to_string(i / 100);
  const int frac = int(i % 100);
  if(frac != 0)
  {
    out += '.';
    out += char('0' + frac / 10);
    if(frac % 10 != 0)
      out += char('0' + frac % 10);
  }
}

std::string fmt(const char* f, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string xml_escape(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    switch(c)
    {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  }
  return out;
}

// Distortion -> [0,1]. D = s^2 + s^-2 + 2 for a pure stretch by s, so
// log s = acosh((D-2)/2)/2: the ramp is linear in the log of the equivalent
// stretch, which spreads the values people care about (4.05 .. 6) over more
// of the ramp than log(D) would, and still compresses outliers.
struct Distortion_scale
{
  double top = 8;
  static double log_stretch(double d) { return d > 4 ? std::acosh((d - 2) / 2) : 0; }
  double operator()(double d) const { return std::min(1.0, log_stretch(d) / log_stretch(top)); }
};

// Round values a reader can compare across images.
const double nice_values[] = {4,  4.05, 4.1, 4.2, 4.5, 5,   6,   8,   10,
                              15, 20,   30,  50,  100, 200, 500, 1000};

// Top of the scale: the smallest nice value above the area-weighted 95th
// percentile, so that a few extreme (often tiny) faces do not wash out the
// rest of the surface.
double pick_top(const Preview_mesh& m)
{
  std::vector<std::pair<double, double>> da; // (distortion, 3D area)
  double total = 0;
  for(std::size_t f = 0; f < m.faces.size(); ++f)
  {
    const double d = m.face_distortion[f];
    if(!std::isfinite(d))
      continue;
    const auto& p0 = m.points[std::size_t(m.faces[f][0])];
    const auto& p1 = m.points[std::size_t(m.faces[f][1])];
    const auto& p2 = m.points[std::size_t(m.faces[f][2])];
    const double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double a = std::sqrt(std::pow(e1[1] * e2[2] - e1[2] * e2[1], 2) + std::pow(e1[2] * e2[0] - e1[0] * e2[2], 2) +
                               std::pow(e1[0] * e2[1] - e1[1] * e2[0], 2));
    da.emplace_back(d, a);
    total += a;
  }
  if(da.empty())
    return 8;
  std::sort(da.begin(), da.end());
  double q = da.back().first, acc = 0;
  for(const auto& x : da)
  {
    acc += x.second;
    if(acc >= 0.95 * total)
    {
      q = x.first;
      break;
    }
  }
  for(double v : nice_values)
    if(v > 4 && v >= q)
      return v;
  return nice_values[sizeof nice_values / sizeof nice_values[0] - 1];
}

} // namespace

bool write_uv_svg(const std::string& path, const Preview_mesh& mesh, const Preview_caption& cap)
{
  if(!valid_mesh(mesh, true))
    return false;
  Box2 box = uv_bounds(mesh);
  double du = box.hi[0] - box.lo[0], dv = box.hi[1] - box.lo[1];
  // Also rejects extents that overflow or scale to non-finite page units.
  if(!(std::max(du, dv) > 0) || !std::isfinite(du) || !std::isfinite(dv) || !std::isfinite(740 / std::max(du, dv)))
    return false;
  // A texture atlas: the page shows the whole unit square, framed.
  const bool in_unit_square = box.lo[0] >= 0 && box.lo[1] >= 0 && box.hi[0] <= 1 && box.hi[1] <= 1;
  if(in_unit_square)
  {
    box = Box2{{0, 0}, {1, 1}};
    du = dv = 1;
  }
  // A scene atlas: every page, side by side, framed.
  if(cap.pages > 0)
  {
    box = Box2{{0, 0}, {preview_page_offset * (cap.pages - 1) + 1, 1}};
    du = box.hi[0];
    dv = 1;
  }

  // Page geometry (SVG user units ~ pixels).
  const double page_w = 1000, margin = 20, top_y = 92, area = 740;
  const double s = area / std::max(du, dv);
  const double layout_h = dv * s;
  const double legend_x = margin + area + 30;
  const double bar_top = top_y + 30, bar_h = 400, bar_w = 22;
  const double page_h = std::max(top_y + layout_h, bar_top + bar_h + 150) + margin;
  auto X = [&](double u) { return margin + (u - box.lo[0]) * s; };
  auto Y = [&](double v) { return top_y + (box.hi[1] - v) * s; }; // v up

  const bool has_d = !mesh.face_distortion.empty();
  Distortion_scale scale;
  if(has_d)
    scale.top = pick_top(mesh);

  // Bin faces by quantized color: one fill per group instead of per face
  // keeps the file small; 64 levels look continuous.
  const int levels = 64;
  const int bin_flipped = -2, bin_no_data = -1;
  std::map<int, std::vector<std::size_t>> groups;
  std::size_t n_flipped = 0;
  bool clipped = false;
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    int bin = bin_no_data;
    if(!(uv_signed_area2(mesh, f) > 0))
    {
      bin = bin_flipped;
      ++n_flipped;
    }
    else if(has_d && std::isfinite(mesh.face_distortion[f]))
    {
      const double d = mesh.face_distortion[f];
      clipped = clipped || d > scale.top;
      bin = std::min(levels - 1, int(scale(d) * levels));
    }
    groups[bin].push_back(f);
  }

  std::string o;
  o.reserve(mesh.faces.size() * 64 + 4096);
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  put_num(o, page_w);
  o += "\" height=\"";
  put_num(o, page_h);
  o += "\" viewBox=\"0 0 ";
  put_num(o, page_w);
  o += ' ';
  put_num(o, page_h);
  o += "\" font-family=\"sans-serif\">\n";
  o += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";

  // Caption.
  o += "<g id=\"caption\">\n<text x=\"20\" y=\"32\" font-size=\"20\" font-weight=\"bold\">" +
       xml_escape(cap.name.empty() ? std::string("UV layout") : cap.name) + "</text>\n";
  // Separate tspans with dx: SVG collapses runs of spaces.
  std::vector<std::string> items{"E_d = " + fmt("%.4f", cap.distortion), "E_s = " + fmt("%.3f", cap.seam_length),
                                 "faces: " + std::to_string(cap.faces), "charts: " + std::to_string(cap.charts)};
  if(cap.seconds >= 0)
    items.push_back("time: " + fmt("%.2f", cap.seconds) + " s");
  o += "<text x=\"20\" y=\"58\" font-size=\"16\">";
  for(std::size_t i = 0; i < items.size(); ++i)
    o += (i ? "<tspan dx=\"28\">" : "<tspan>") + items[i] + "</tspan>";
  o += "</text>\n";
  // The atlas' figures; what breaks an atlas (overlaps, flips) in magenta.
  std::vector<std::string> atlas;
  const std::string alarm = " fill=\"" + hex(flipped_rgb) + "\" font-weight=\"bold\"";
  if(cap.coverage >= 0)
    atlas.push_back(">coverage: " + fmt("%.1f", 100 * cap.coverage) + " %");
  if(cap.border_crossings >= 0)
    atlas.push_back((cap.border_crossings > 0 ? alarm : std::string()) +
                    ">border crossings: " + std::to_string(cap.border_crossings));
  if(n_flipped > 0)
    atlas.push_back(alarm + ">flipped faces: " + std::to_string(n_flipped));
  if(!atlas.empty())
  {
    o += "<text x=\"20\" y=\"78\" font-size=\"14\">";
    for(std::size_t i = 0; i < atlas.size(); ++i)
      o += (i ? "<tspan dx=\"28\"" : "<tspan") + atlas[i] + "</tspan>";
    o += "</text>\n";
  }
  o += "</g>\n";

  // The texture's frame, under the faces.
  if(in_unit_square)
  {
    o += "<rect id=\"unit-square\" x=\"";
    put_num(o, X(0));
    o += "\" y=\"";
    put_num(o, Y(1));
    o += "\" width=\"";
    put_num(o, s);
    o += "\" height=\"";
    put_num(o, s);
    o += "\" fill=\"none\" stroke=\"#808080\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>\n";
  }
  for(int page = 0; page < cap.pages; ++page)
  {
    o += "<rect id=\"page-" + std::to_string(page) + "\" x=\"";
    put_num(o, X(preview_page_offset * page));
    o += "\" y=\"";
    put_num(o, Y(1));
    o += "\" width=\"";
    put_num(o, s);
    o += "\" height=\"";
    put_num(o, s);
    o += "\" fill=\"none\" stroke=\"#808080\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>\n";
  }

  // Faces. crispEdges: antialiased edges of abutting polygons would let the
  // white background bleed through as hairlines.
  o += "<g id=\"faces\" shape-rendering=\"crispEdges\">\n";
  // Flipped faces last, so overlapping valid faces cannot hide them.
  std::vector<std::pair<int, std::vector<std::size_t>>> ordered(groups.begin(), groups.end());
  std::stable_partition(ordered.begin(), ordered.end(), [&](const auto& g) { return g.first != bin_flipped; });
  for(const auto& g : ordered)
  {
    Rgb c = g.first == bin_flipped   ? flipped_rgb
            : g.first == bin_no_data ? no_data_rgb
                                     : viridis((g.first + 0.5) / levels);
    o += "<g fill=\"" + hex(c) + "\">\n";
    for(std::size_t f : g.second)
    {
      o += "<polygon points=\"";
      for(int k = 0; k < 3; ++k)
      {
        if(k)
          o += ' ';
        put_num(o, X(mesh.corner_uv[f][k][0]));
        o += ',';
        put_num(o, Y(mesh.corner_uv[f][k][1]));
      }
      o += "\"/>\n";
    }
    o += "</g>\n";
  }
  o += "</g>\n";

  // Edges as one path per kind: boundary of the charts, then seams on top.
  auto seg = [&](std::string& d, std::size_t f, int k) {
    const auto& a = mesh.corner_uv[f][k];
    const auto& b = mesh.corner_uv[f][(k + 1) % 3];
    d += 'M';
    put_num(d, X(a[0]));
    d += ' ';
    put_num(d, Y(a[1]));
    d += 'L';
    put_num(d, X(b[0]));
    d += ' ';
    put_num(d, Y(b[1]));
  };
  std::string outline;
  for(const auto& e : uv_boundary_edges(mesh))
    seg(outline, e.first, e.second);
  o += "<path id=\"chart-outlines\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\" "
       "stroke-linecap=\"round\" d=\"" +
       outline + "\"/>\n";

  std::unordered_set<std::uint64_t> seams;
  for(const auto& e : mesh.seam_edges)
    seams.insert(edge_key(e.first, e.second));
  std::string seam_d;
  if(!seams.empty())
    for(std::size_t f = 0; f < mesh.faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
        if(seams.count(edge_key(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3])))
          seg(seam_d, f, k); // each seam is drawn on both of its UV sides
  if(!seam_d.empty())
    o += "<path id=\"seams\" fill=\"none\" stroke=\"" + hex(seam_rgb) +
         "\" stroke-width=\"2.5\" stroke-linecap=\"round\" d=\"" + seam_d + "\"/>\n";

  // Legend: color bar with ticks, then line/face swatches.
  o += "<g id=\"legend\" font-size=\"13\">\n";
  auto text = [&](double x, double y, const std::string& t, const char* extra = "") {
    o += "<text x=\"";
    put_num(o, x);
    o += "\" y=\"";
    put_num(o, y);
    o += "\"";
    o += extra;
    o += ">" + t + "</text>\n";
  };
  double y = bar_top + bar_h + 30;
  if(has_d)
  {
    text(legend_x, top_y, "distortion", " font-weight=\"bold\"");
    text(legend_x, top_y + 16, "(4 = isometric)");
    o += "<defs><linearGradient id=\"ramp\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n";
    for(int i = 0; i <= 8; ++i)
      o += "<stop offset=\"" + fmt("%.3f", i / 8.0) + "\" stop-color=\"" + hex(viridis(i / 8.0)) + "\"/>\n";
    o += "</linearGradient></defs>\n";
    o += "<rect x=\"" + fmt("%.0f", legend_x) + "\" y=\"" + fmt("%.0f", bar_top) + "\" width=\"" +
         fmt("%.0f", bar_w) + "\" height=\"" + fmt("%.0f", bar_h) +
         "\" fill=\"url(#ramp)\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
    // Ticks: the ends always, then nice values in between that keep labels
    // at least 18 units apart.
    std::vector<double> ticks{4, scale.top};
    for(double v : nice_values)
    {
      if(v <= 4 || v >= scale.top)
        continue;
      bool room = true;
      for(double t : ticks)
        room = room && std::abs(scale(v) - scale(t)) * bar_h >= 18;
      if(room)
        ticks.push_back(v);
    }
    std::sort(ticks.begin(), ticks.end());
    for(double v : ticks)
    {
      const double ty = bar_top + bar_h * (1 - scale(v));
      o += "<path d=\"M" + fmt("%.1f", legend_x + bar_w) + ' ' + fmt("%.1f", ty) + "h6\" stroke=\"#000000\"/>\n";
      std::string label = (v == scale.top && clipped ? "\xe2\x89\xa5 " : "") + fmt("%g", v);
      text(legend_x + bar_w + 9, ty + 4.5, label);
    }
  }
  else
  {
    y = top_y + 10;
  }
  auto swatch_line = [&](const Rgb& c, double w, const std::string& label) {
    o += "<path d=\"M" + fmt("%.0f", legend_x) + ' ' + fmt("%.1f", y) + "h26\" stroke=\"" + hex(c) +
         "\" stroke-width=\"" + fmt("%g", w) + "\"/>\n";
    text(legend_x + 34, y + 4.5, label);
    y += 22;
  };
  auto swatch_box = [&](const Rgb& c, const std::string& label) {
    o += "<rect x=\"" + fmt("%.0f", legend_x) + "\" y=\"" + fmt("%.1f", y - 7) + "\" width=\"26\" height=\"14\" fill=\"" +
         hex(c) + "\"/>\n";
    text(legend_x + 34, y + 4.5, label);
    y += 22;
  };
  swatch_line(seam_rgb, 2.5, "seam");
  swatch_line({0, 0, 0}, 1, "chart boundary");
  if(in_unit_square)
  {
    o += "<path d=\"M" + fmt("%.0f", legend_x) + ' ' + fmt("%.1f", y) +
         "h26\" stroke=\"#808080\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>\n";
    text(legend_x + 34, y + 4.5, "unit square (texture)");
    y += 22;
  }
  if(n_flipped > 0)
    swatch_box(flipped_rgb, "flipped face");
  if(!has_d)
    swatch_box(no_data_rgb, "no distortion data");
  o += "</g>\n</svg>\n";

  std::ofstream out(path, std::ios::binary);
  if(!out)
    return false;
  out.write(o.data(), std::streamsize(o.size()));
  return bool(out);
}
