// Checks of a cut_and_parameterize() result that recompute everything from
// the outputs (the seam edge map and the halfedge UV map) with the mesh's own
// halfedge structure, independently of the library's internal topology code:
//
//   Cut_run<Mesh> run(mesh);                       // storage for the outputs
//   run.run(SMP::parameters::lambda(2.));          // calls cut_and_parameterize
//   const Chart_report charts = check_cut_result(mesh, run);
//
// check_cut_result() CHECKs that the run succeeded, UVs are finite and no UV
// triangle is flipped, seams are interior mesh edges that, with the input
// border, form one connected graph per mesh component, the UVs are one per
// corner class of the mesh cut along the seams (identical across uncut
// edges; border halfedges carry their corner's UV), every chart (component
// of faces joined across uncut interior edges) is a topological disk
// (χ = 1, one boundary loop, a manifold boundary), the charts' UV bounding
// boxes are pairwise disjoint, no UV border crosses another and no UV area
// is covered twice (unless the run allowed overlaps), UVs lie in the unit square (unless in world units), and
// the reported statistics (charts, seam edges, E_d, E_s, crossings, coverage)
// match what the outputs say.
#ifndef CUT_PARAM_TEST_CUT_RESULT_CHECKS_H
#define CUT_PARAM_TEST_CUT_RESULT_CHECKS_H

#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <boost/property_map/property_map.hpp>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace cut_test {

namespace SMP_ = CGAL::Surface_mesh_parameterization;

/// Storage of the outputs of one cut_and_parameterize() call, for any mesh type.
template <typename Mesh>
struct Cut_run
{
  using GT = boost::graph_traits<Mesh>;
  using edge_descriptor = typename GT::edge_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

  using face_descriptor = typename GT::face_descriptor;

  const Mesh& mesh;
  std::unordered_map<edge_descriptor, bool> seam_storage;
  std::unordered_map<halfedge_descriptor, Point_2> uv_storage;
  std::unordered_map<face_descriptor, double> v_storage; // for face_discontinuity_map(v())
  SMP_::Cut_and_parameterize_result result;

  explicit Cut_run(const Mesh& m) : mesh(m)
  {
    for(edge_descriptor e : edges(mesh)) seam_storage[e] = false;
    for(halfedge_descriptor h : halfedges(mesh)) uv_storage[h] = Point_2(0., 0.);
    for(face_descriptor f : faces(mesh)) v_storage[f] = 0.;
  }

  /// Fills the outputs with values no run writes (a distinct UV off the unit
  /// square per halfedge, v = -0.375 - k per face) and keeps them, with the
  /// seam flags as they are (an input too: the given seams), for
  /// expect_outputs_untouched().
  void fill_sentinels()
  {
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges(mesh))
    {
      uv_storage[h] = Point_2(-7.25 - double(k), 3.5 + 0.5 * double(k));
      ++k;
    }
    k = 0;
    for(face_descriptor f : faces(mesh)) v_storage[f] = -0.375 - double(k++);
    sentinel_seams = seam_storage;
    sentinel_uvs = uv_storage;
    sentinel_v = v_storage;
  }
  /// Expects every output (seams, UVs, v) as fill_sentinels() left it, bit for bit.
  void expect_outputs_untouched() const
  {
    ASSERT_FALSE(sentinel_uvs.empty()) << "call fill_sentinels() before the run";
    std::size_t seams_changed = 0, uvs_changed = 0, v_changed = 0;
    for(edge_descriptor e : edges(mesh)) seams_changed += seam_storage.at(e) != sentinel_seams.at(e) ? 1 : 0;
    for(halfedge_descriptor h : halfedges(mesh))
      uvs_changed += std::memcmp(&uv_storage.at(h), &sentinel_uvs.at(h), sizeof(Point_2)) != 0 ? 1 : 0;
    for(face_descriptor f : faces(mesh))
      v_changed += std::memcmp(&v_storage.at(f), &sentinel_v.at(f), sizeof(double)) != 0 ? 1 : 0;
    EXPECT_EQ(seams_changed, std::size_t(0)) << "seam flags written on error";
    EXPECT_EQ(uvs_changed, std::size_t(0)) << "UVs written on error";
    EXPECT_EQ(v_changed, std::size_t(0)) << "v written on error";
  }
  std::unordered_map<edge_descriptor, bool> sentinel_seams;
  std::unordered_map<halfedge_descriptor, Point_2> sentinel_uvs;
  std::unordered_map<face_descriptor, double> sentinel_v;

  boost::associative_property_map<std::unordered_map<edge_descriptor, bool>> seams()
  {
    return boost::associative_property_map<std::unordered_map<edge_descriptor, bool>>(seam_storage);
  }
  boost::associative_property_map<std::unordered_map<halfedge_descriptor, Point_2>> uvs()
  {
    return boost::associative_property_map<std::unordered_map<halfedge_descriptor, Point_2>>(uv_storage);
  }
  boost::associative_property_map<std::unordered_map<face_descriptor, double>> v()
  {
    return boost::associative_property_map<std::unordered_map<face_descriptor, double>>(v_storage);
  }

  bool is_seam(edge_descriptor e) const { return seam_storage.at(e); }
  const Point_2& uv(halfedge_descriptor h) const { return uv_storage.at(h); }

  /// The atlas options of the last run (what check_cut_result() expects).
  bool injective = true, world_units = false;

  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const SMP_::Cut_and_parameterize_result& run(const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    injective = choose_parameter(get_parameter(np, SMP_::internal_np::global_injectivity), true);
    world_units = choose_parameter(get_parameter(np, SMP_::internal_np::world_units), false);
    result = SMP_::cut_and_parameterize(mesh, seams(), uvs(), np);
    return result;
  }


  /// Seam flags in the order of edges(mesh).
  std::vector<char> seam_vector() const
  {
    std::vector<char> s;
    for(edge_descriptor e : edges(mesh)) s.push_back(seam_storage.at(e) ? 1 : 0);
    return s;
  }
  /// UVs of the face halfedges in the order of halfedges(mesh).
  std::vector<Point_2> uv_vector() const
  {
    std::vector<Point_2> u;
    for(halfedge_descriptor h : halfedges(mesh))
      if(!is_border(h, mesh)) u.push_back(uv_storage.at(h));
    return u;
  }
  std::size_t number_of_seam_edges() const
  {
    std::size_t n = 0;
    for(const auto& s : seam_storage) n += s.second ? 1 : 0;
    return n;
  }
};

/// Asserts that every run of `seams` and `uvs` (seam_vector(), uv_vector())
/// gave the first one's outputs, bit for bit.
inline void expect_identical_outputs(const std::vector<std::vector<char>>& seams,
                                     const std::vector<std::vector<Point_2>>& uvs)
{
  for(std::size_t i = 1; i < uvs.size(); ++i)
  {
    EXPECT_TRUE(seams[i] == seams[0]) << "run " << i;
    ASSERT_EQ(uvs[i].size(), uvs[0].size()) << "run " << i;
    std::size_t differ = 0;
    for(std::size_t k = 0; k < uvs[0].size(); ++k)
      if(std::memcmp(&uvs[i][k], &uvs[0][k], sizeof(Point_2)) != 0) ++differ;
    EXPECT_EQ(differ, std::size_t(0)) << "run " << i;
  }
}

/// Runs `run(Cut_run<Mesh>&)` (which calls Cut_run::run() with the options
/// under test and returns its result) on `mesh` once per number of TBB
/// threads in `threads`, and asserts that every run gave the first one's
/// seams, UVs (bit for bit) and Newton iterations. Without TBB the calling
/// test is skipped (GTEST_SKIP: CTest shows it), not left out.
template <typename Mesh, typename Run>
void expect_same_result_for_thread_counts(const Mesh& mesh, std::initializer_list<int> threads, Run run)
{
#ifndef CGAL_LINKED_WITH_TBB
  (void)mesh;
  (void)threads;
  (void)run;
  GTEST_SKIP() << "built without TBB: one thread only";
#else
  std::vector<std::vector<Point_2>> uvs;
  std::vector<std::vector<char>> seams;
  std::vector<std::size_t> newton;
  for(int t : threads)
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(t));
    Cut_run<Mesh> r(mesh);
    ASSERT_TRUE(run(r).ok()) << t << " threads";
    uvs.push_back(r.uv_vector());
    seams.push_back(r.seam_vector());
    newton.push_back(r.result.newton_iterations);
  }
  expect_identical_outputs(seams, uvs);
  for(std::size_t i = 1; i < newton.size(); ++i) EXPECT_EQ(newton[i], newton[0]) << "run " << i;
#endif
}

/// Charts of the cut mesh, as computed by check_cut_result().
template <typename Mesh>
struct Chart_report
{
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  std::size_t number_of_charts = 0;
  std::unordered_map<face_descriptor, int> chart_of_face;
  std::vector<long> euler;                 // per chart
  std::vector<std::size_t> loops;          // per chart
  std::vector<std::array<double, 4>> box;  // per chart: xmin, ymin, xmax, ymax
  bool valid = false;                      // the run succeeded and the checks could run
};

/// 3D length of an edge.
template <typename Mesh>
double edge_length_3(const Mesh& mesh, typename boost::graph_traits<Mesh>::edge_descriptor e)
{
  auto vpm = get(CGAL::vertex_point, mesh);
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, mesh)), get(vpm, target(e, mesh)))));
}

/// See the file comment.
template <typename Mesh>
Chart_report<Mesh> check_cut_result(const Mesh& mesh, const Cut_run<Mesh>& run)
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  Chart_report<Mesh> report;
  CUT_ASSERT_TRUE(run.result.ok()) << "cut_and_parameterize failed: " << SMP_::error_name(run.result.error);

  // --- seams are interior mesh edges; their count is the reported one
  std::size_t seam_edges = 0;
  for(edge_descriptor e : edges(mesh))
    if(run.is_seam(e))
    {
      ++seam_edges;
      EXPECT_TRUE(!is_border(e, mesh)) << "a seam edge is on the mesh's boundary";
    }
  EXPECT_EQ(seam_edges, run.result.number_of_seam_edges);

  // --- per connected component of the mesh, the seams together with the
  // input border form one connected graph: a chart's boundary is one loop,
  // so the seam/border edges around a set of charts that is closed under
  // crossing seams (i.e. a whole mesh component) are connected. A seam piece
  // floating apart from the rest (e.g. a closed slit inside a chart) would
  // leave a chart with a second boundary loop.
  {
    using vertex_descriptor = typename GT::vertex_descriptor;
    using Up = std::unordered_map<vertex_descriptor, vertex_descriptor>;
    auto root = [](Up& up, vertex_descriptor v) {
      auto it = up.find(v);
      if(it == up.end()) { up.emplace(v, v); return v; }
      while(up.at(v) != v) v = up[v] = up.at(up.at(v));
      return v;
    };
    auto join = [&](Up& up, vertex_descriptor a, vertex_descriptor b) {
      a = root(up, a); b = root(up, b);
      if(a != b) up[a] = b;
    };
    Up component, cut_graph;
    for(edge_descriptor e : edges(mesh))
    {
      join(component, source(e, mesh), target(e, mesh));
      if(run.is_seam(e) || is_border(e, mesh)) join(cut_graph, source(e, mesh), target(e, mesh));
    }
    std::unordered_map<vertex_descriptor, std::vector<vertex_descriptor>> pieces; // mesh component -> cut-graph roots
    std::unordered_map<vertex_descriptor, std::size_t> piece_edges;
    std::vector<vertex_descriptor> on_cut_graph;
    for(const auto& entry : cut_graph) on_cut_graph.push_back(entry.first);
    for(vertex_descriptor v : on_cut_graph)
    {
      const vertex_descriptor r = root(cut_graph, v);
      if(r != v) continue;
      pieces[root(component, v)].push_back(r);
    }
    for(edge_descriptor e : edges(mesh))
      if(run.is_seam(e) || is_border(e, mesh)) ++piece_edges[root(cut_graph, source(e, mesh))];
    for(const auto& entry : pieces)
      if(entry.second.size() > 1)
      {
        std::vector<std::size_t> counts;
        for(vertex_descriptor r : entry.second) counts.push_back(piece_edges[r]);
        std::sort(counts.begin(), counts.end());
        std::ostringstream sizes;
        for(std::size_t c : counts) sizes << " " << c;
        EXPECT_TRUE(false) << "the seams and border of a mesh component form " << entry.second.size()
                         << " separate pieces (edges:" << sizes.str() << "): some seam floats inside a chart";
      }
  }

  // --- UVs finite, no flipped face (signed area recomputed here)
  std::size_t non_finite = 0, flipped = 0;
  for(face_descriptor f : faces(mesh))
  {
    const halfedge_descriptor h0 = halfedge(f, mesh), h1 = next(h0, mesh), h2 = next(h1, mesh);
    const Point_2 a = run.uv(h0), b = run.uv(h1), c = run.uv(h2);
    for(const Point_2& p : {a, b, c})
    {
      if(!std::isfinite(p.x()) || !std::isfinite(p.y())) ++non_finite;
    }
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if(!(area2 > 0.)) ++flipped;
  }
  EXPECT_EQ(non_finite, std::size_t(0));
  EXPECT_EQ(flipped, std::size_t(0));
  EXPECT_EQ(SMP_::number_of_flipped_faces(mesh, const_cast<Cut_run<Mesh>&>(run).uvs()), std::size_t(0));
  CUT_ASSERT_TRUE(non_finite == 0);

  // --- corner classes: corner = face halfedge h (the corner at target(h) in
  // face(h)); across an uncut interior edge the corners at each end are one
  std::vector<halfedge_descriptor> corners;
  std::unordered_map<halfedge_descriptor, int> corner_index;
  for(halfedge_descriptor h : halfedges(mesh))
    if(!is_border(h, mesh))
    {
      corner_index.emplace(h, int(corners.size()));
      corners.push_back(h);
    }
  std::vector<int> parent(corners.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) { while(parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  auto unite = [&](int a, int b) { a = find(a); b = find(b); if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b); };
  // faces: joined across uncut interior edges
  std::unordered_map<face_descriptor, int> face_index;
  std::vector<face_descriptor> face_list;
  for(face_descriptor f : faces(mesh))
  {
    face_index.emplace(f, int(face_list.size()));
    face_list.push_back(f);
  }
  std::vector<int> face_parent(face_list.size());
  std::iota(face_parent.begin(), face_parent.end(), 0);
  auto find_face = [&](int x) { while(face_parent[x] != x) x = face_parent[x] = face_parent[face_parent[x]]; return x; };
  auto is_chart_boundary = [&](halfedge_descriptor h) { // h a face halfedge
    return is_border(opposite(h, mesh), mesh) || run.is_seam(edge(h, mesh));
  };
  for(edge_descriptor e : edges(mesh))
  {
    const halfedge_descriptor h = halfedge(e, mesh), o = opposite(h, mesh);
    if(is_border(h, mesh) || is_border(o, mesh) || run.is_seam(e)) continue;
    unite(corner_index.at(h), corner_index.at(prev(o, mesh)));  // at target(h) = source(o)
    unite(corner_index.at(prev(h, mesh)), corner_index.at(o));  // at source(h) = target(o)
    const int a = find_face(face_index.at(face(h, mesh))), b = find_face(face_index.at(face(o, mesh)));
    if(a != b) face_parent[(std::max)(a, b)] = (std::min)(a, b);
  }

  // --- one UV per corner class (exactly: the library stores one per class)
  std::size_t class_mismatch = 0;
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    const Point_2& p = run.uv(corners[c]);
    const Point_2& q = run.uv(corners[find(int(c))]);
    if(p != q) ++class_mismatch;
  }
  EXPECT_TRUE(class_mismatch == 0) << class_mismatch << " corners differ from their class across uncut edges";
  // border halfedges carry the UV of the corner at their target in the face across
  std::size_t border_mismatch = 0;
  for(halfedge_descriptor b : halfedges(mesh))
    if(is_border(b, mesh) && run.uv(b) != run.uv(prev(opposite(b, mesh), mesh))) ++border_mismatch;
  EXPECT_EQ(border_mismatch, std::size_t(0));

  // --- charts
  std::unordered_map<int, int> chart_id;
  for(std::size_t f = 0; f < face_list.size(); ++f)
  {
    const int id = chart_id.emplace(find_face(int(f)), int(chart_id.size())).first->second;
    report.chart_of_face.emplace(face_list[f], id);
  }
  const std::size_t n_charts = chart_id.size();
  report.number_of_charts = n_charts;
  EXPECT_EQ(run.result.number_of_charts, n_charts);

  // a corner class lies in one chart (classes are joined only across uncut edges)
  std::vector<int> chart_of_class(corners.size(), -1);
  std::size_t class_in_two_charts = 0;
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    const int chart = report.chart_of_face.at(face(corners[c], mesh));
    int& k = chart_of_class[find(int(c))];
    if(k < 0) k = chart;
    else if(k != chart) ++class_in_two_charts;
  }
  EXPECT_EQ(class_in_two_charts, std::size_t(0));

  // Euler characteristic V - E + F per chart: V = classes, E = boundary
  // halfedges + interior halfedges / 2, F = faces
  std::vector<long> V(n_charts, 0), E2(n_charts, 0), F(n_charts, 0);
  for(std::size_t c = 0; c < corners.size(); ++c)
    if(find(int(c)) == int(c)) ++V[chart_of_class[c]];
  for(face_descriptor f : faces(mesh)) ++F[report.chart_of_face.at(f)];
  // boundary of the cut mesh: a face halfedge h on a seam or across the mesh
  // border runs from class(prev(h)) to class(h)
  std::unordered_map<int, int> boundary_next, boundary_in;
  std::size_t boundary_non_manifold = 0;
  for(halfedge_descriptor h : corners)
  {
    const int chart = report.chart_of_face.at(face(h, mesh));
    if(is_chart_boundary(h))
    {
      E2[chart] += 2;
      const int from = find(corner_index.at(prev(h, mesh))), to = find(corner_index.at(h));
      if(!boundary_next.emplace(from, to).second) ++boundary_non_manifold;
      if(++boundary_in[to] > 1) ++boundary_non_manifold;
    }
    else
      E2[chart] += 1;
  }
  EXPECT_TRUE(boundary_non_manifold == 0) << boundary_non_manifold << " cut-mesh vertices with several boundary sectors";
  report.euler.assign(n_charts, 0);
  report.loops.assign(n_charts, 0);
  for(std::size_t k = 0; k < n_charts; ++k) report.euler[k] = V[k] - E2[k] / 2 + F[k];
  std::unordered_map<int, bool> visited;
  for(const auto& entry : boundary_next)
  {
    if(visited[entry.first]) continue;
    ++report.loops[chart_of_class[entry.first]];
    int v = entry.first;
    while(!visited[v])
    {
      visited[v] = true;
      auto it = boundary_next.find(v);
      if(it == boundary_next.end()) break; // open chain: non-manifold, reported above
      v = it->second;
    }
  }
  std::size_t not_disks = 0;
  for(std::size_t k = 0; k < n_charts; ++k)
    if(report.euler[k] != 1 || report.loops[k] != 1)
    {
      ++not_disks;
      EXPECT_TRUE(false) << "chart " << k << " is not a disk: chi " << report.euler[k] << ", "
                                << report.loops[k] << " boundary loops, " << F[k] << " faces";
    }
  EXPECT_EQ(not_disks, std::size_t(0));

  // --- chart UV bounding boxes (charts packed by shape may nest in one
  // another's box: that they are apart is the overlap and crossing checks below)
  const double inf = std::numeric_limits<double>::infinity();
  report.box.assign(n_charts, {inf, inf, -inf, -inf});
  for(halfedge_descriptor h : corners)
  {
    auto& b = report.box[report.chart_of_face.at(face(h, mesh))];
    const Point_2& p = run.uv(h);
    b[0] = (std::min)(b[0], p.x());
    b[1] = (std::min)(b[1], p.y());
    b[2] = (std::max)(b[2], p.x());
    b[3] = (std::max)(b[3], p.y());
  }

  // --- the atlas: no crossing border (unless allowed), UVs in the unit
  // square (unless in world units), the reported coverage and crossings
  auto& mutable_run = const_cast<Cut_run<Mesh>&>(run);
  const std::size_t crossings = SMP_::number_of_border_crossings(mesh, mutable_run.uvs());
  EXPECT_EQ(crossings, run.result.border_crossings);
  if(run.injective) EXPECT_EQ(crossings, std::size_t(0));
  // charts stacked or nested cross no border: the area covered twice sees
  // them (256 x 256 samples: cheap enough for every run of the suite)
  if(run.injective) EXPECT_EQ(SMP_::uv_overlap_area(mesh, mutable_run.uvs(), 256), 0.);
  EXPECT_TRUE(run.result.uv_scale > 0. && std::isfinite(run.result.uv_scale));
  if(run.world_units)
    EXPECT_EQ(run.result.uv_scale, 1.);
  else
  {
    std::size_t outside = 0;
    for(halfedge_descriptor h : halfedges(mesh))
    {
      const Point_2& p = run.uv(h);
      if(!(p.x() >= 0. && p.x() <= 1. && p.y() >= 0. && p.y() <= 1.)) ++outside;
    }
    EXPECT_TRUE(outside == 0) << outside << " UVs outside the unit square";
    EXPECT_REL(SMP_::uv_area(mesh, mutable_run.uvs()), run.result.uv_coverage, 1e-9);
  }

  // --- reported E_d and E_s are those of the outputs (E_d in 3D units); of
  // a face whose rest shape was clamped (number_of_degenerate_faces), those
  // of the clamped shape (CGAL's mpi_triang.off, one needle: E_d and E_s
  // within 7e-7 and 3e-6, relative)
  const double energy = SMP_::distortion_energy(mesh, mutable_run.uvs(), SMP_::parameters::uv_scale(run.result.uv_scale));
  EXPECT_TRUE(std::isfinite(run.result.distortion) && run.result.distortion >= 4. - 1e-9);
  const double exact = run.result.number_of_degenerate_faces == 0 ? 1e-9 : 1e-5;
  EXPECT_REL(energy, run.result.distortion, exact);
  double seam_length = 0.;
  for(edge_descriptor e : edges(mesh))
    if(run.is_seam(e)) seam_length += edge_length_3(mesh, e);
  const double expected_es = seam_length / std::sqrt(SMP_::surface_area(mesh) / pi);
  EXPECT_NEAR(run.result.seam_length, expected_es, exact * (1. + expected_es));
  report.valid = true;
  return report;
}

} // namespace cut_test

#endif
