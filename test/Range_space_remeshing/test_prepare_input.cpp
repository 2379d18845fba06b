// prepare_input()'s mesh from a soup: the same mesh as CGAL's
// polygon_soup_to_polygon_mesh() (vertices, faces, edges and their directions, in
// order; borders linked), for any model of MutableFaceGraph, and without a cost
// quadratic in a vertex's valence (a fan of 300,000 triangles around one point: ctest's
// timeout for this test is the guard; CGAL's builder takes minutes there).
// argv[1]: the folder of CGAL's sample meshes.
#include "test_support.h"

#include <CGAL/Range_space_remeshing/prepare_input.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace test;

namespace {

using Polygons = std::vector<std::vector<std::size_t>>;

/// The soup of `mesh`: its points in vertex order, its faces from their halfedge.
void soup_of(const Mesh& mesh, std::vector<Point>& points, Polygons& polygons)
{
  for(auto v : vertices(mesh))
    points.push_back(mesh.point(v));
  for(auto f : faces(mesh)) {
    polygons.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(std::size_t(v));
  }
}

/// The corners of each face from its halfedge, the endpoints of each edge's halfedge.
template <class PolygonMesh>
std::vector<std::size_t> structure_of(const PolygonMesh& mesh)
{
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(mesh);
  std::vector<std::size_t> s;
  for(auto f : faces(mesh)) {
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      s.push_back(get(vertex_index, v));
    s.push_back(std::size_t(-1));
  }
  for(auto e : edges(mesh)) {
    s.push_back(get(vertex_index, source(halfedge(e, mesh), mesh)));
    s.push_back(get(vertex_index, target(halfedge(e, mesh), mesh)));
  }
  return s;
}

/// The lengths of the border cycles, and whether each border vertex's halfedge is on
/// the border (CGAL's convention, which is_border(v) relies on).
template <class PolygonMesh>
std::vector<std::size_t> borders_of(const PolygonMesh& mesh)
{
  std::vector<std::size_t> lengths;
  std::set<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> seen;
  for(auto h : halfedges(mesh)) {
    if(!is_border(h, mesh) || seen.count(h))
      continue;
    std::size_t length = 0;
    for(auto g : CGAL::halfedges_around_face(h, mesh)) {
      seen.insert(g);
      ++length;
      CHECK(is_border(halfedge(target(g, mesh), mesh), mesh));
    }
    lengths.push_back(length);
  }
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

/// The soups of CGAL's sample meshes (closed, with borders, several components) give
/// what CGAL's builder gives.
void test_same_mesh_as_cgal(const std::string& folder)
{
  for(const char* name : {"elephant.off", "elephant-with-holes.off", "mech-holes-shark.off", "bones.off",
                          "fandisk.off"}) {
    Mesh input;
    CHECK(CGAL::IO::read_polygon_mesh(folder + "/" + name, input) && CGAL::is_triangle_mesh(input));
    std::vector<Point> points;
    Polygons polygons;
    soup_of(input, points, polygons);
    Mesh ours, cgal;
    std::vector<Point> points_copy = points;
    Polygons polygons_copy = polygons;
    const auto repairs = RSR::prepare_input(points_copy, polygons_copy, ours);
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, cgal);
    std::cout << name << ": " << num_faces(ours) << " faces, " << borders_of(ours).size() << " border cycles"
              << std::endl;
    CHECK(!repairs.repaired());
    CHECK(CGAL::is_valid_polygon_mesh(ours));
    CHECK_EQ(num_vertices(ours), num_vertices(cgal));
    CHECK_EQ(num_halfedges(ours), num_halfedges(cgal));
    CHECK(structure_of(ours) == structure_of(cgal));
    CHECK(borders_of(ours) == borders_of(cgal));

    using Polyhedron = CGAL::Polyhedron_3<K>;
    Polyhedron polyhedron;
    points_copy = points;
    polygons_copy = polygons;
    RSR::prepare_input(points_copy, polygons_copy, polyhedron);
    CHECK(CGAL::is_valid_polygon_mesh(polyhedron));
    CHECK(structure_of(polyhedron) == structure_of(cgal));
    CHECK(borders_of(polyhedron) == borders_of(cgal));
  }
}

/// A cone of `n` triangles around its apex, closed by one n-gon (split into a fan
/// from its first corner): two vertices of valence n.
void test_vertex_of_huge_valence()
{
  const std::size_t n = 300000;
  std::vector<Point> points{Point(0, 0, 1)};
  Polygons polygons;
  std::vector<std::size_t> base;
  for(std::size_t i = 0; i < n; ++i) {
    const double angle = 2 * CGAL_PI * double(i) / double(n);
    points.emplace_back(std::cos(angle), std::sin(angle), 0);
    polygons.push_back({0, 1 + i, 1 + (i + 1) % n});
    base.push_back(n - i);
  }
  polygons.push_back(base);
  Mesh mesh;
  const auto repairs = RSR::prepare_input(points, polygons, mesh);
  CHECK_EQ(repairs.triangulated_polygons, std::size_t(1));
  CHECK(CGAL::is_valid_polygon_mesh(mesh));
  CHECK(CGAL::is_closed(mesh));
  CHECK_EQ(num_faces(mesh), Mesh::size_type(2 * n - 2));
  CHECK_EQ(euler_characteristic(mesh), 2L);
}

/// Two quadrilaterals around a vertex of valence 2 (as a quad remesh can have) whose
/// shorter diagonals are the same segment: split along it, both gave one triangle
/// (twice, reversed) and the soup was refused as non-manifold.
void test_quadrilaterals_around_a_vertex_of_valence_2()
{
  // a, b, c, d a rhombus long in x; v, inside, is a corner of both quadrilaterals
  const std::vector<Point> points{Point(-2, 0, 0), Point(0, 0.5, 0), Point(2, 0, 0), Point(0, -0.5, 0),
                                  Point(0.1, 0, 0)};
  std::vector<Point> soup_points = points;
  Polygons polygons{{0, 1, 4, 3}, {1, 2, 3, 4}};
  Mesh mesh;
  const auto repairs = RSR::prepare_input(soup_points, polygons, mesh, RSR::Input_repair::REFUSE);
  CHECK(!repairs.repaired());
  CHECK_EQ(repairs.triangulated_polygons, std::size_t(2));
  CHECK(CGAL::is_valid_polygon_mesh(mesh));
  CHECK_EQ(num_faces(mesh), Mesh::size_type(4));
  CHECK_EQ(euler_characteristic(mesh), 1L);
  CHECK(borders_of(mesh) == std::vector<std::size_t>{4});
}

/// The same when one of the two quadrilaterals is non-convex (in the plane where it is
/// widest), its reflex corner at an end of the diagonal the other one took: split by
/// its triangulation, it repeated the other's triangle. Two quadrilaterals of a
/// remesh of CGAL's bones.off (--seeded --cell-size 0.03), each order of the two.
void test_non_convex_quadrilateral_around_a_vertex_of_valence_2()
{
  const std::vector<Point> points{Point(1.1819116998625316, -0.4607286683042916, 0.035583120634886459),
                                  Point(0.85212141474569092, -0.66526157489075999, 0.26457009472307946),
                                  Point(0.95028174090178286, -0.48969402056335465, -0.14429892445293538),
                                  Point(1.1003154933836465, -0.38865172690229388, -0.0075148480529919591),
                                  Point(0.91732294615073584, -0.21752597962627607, 0.099976839468273626)};
  for(const Polygons& quadrilaterals : {Polygons{{0, 1, 2, 3}, {0, 3, 4, 1}}, Polygons{{0, 3, 4, 1}, {0, 1, 2, 3}}}) {
    Polygons polygons = quadrilaterals;
    RSR::internal::split_polygons(points, polygons);
    std::set<std::set<std::size_t>> triangles;
    for(const auto& triangle : polygons)
      triangles.insert(std::set<std::size_t>(triangle.begin(), triangle.end()));
    CHECK_EQ(polygons.size(), std::size_t(4));
    CHECK_EQ(triangles.size(), std::size_t(4)); // none twice
    std::vector<Point> soup_points = points;
    polygons = quadrilaterals;
    Mesh mesh;
    RSR::prepare_input(soup_points, polygons, mesh, RSR::Input_repair::REFUSE);
    CHECK(CGAL::is_valid_polygon_mesh(mesh));
    CHECK_EQ(num_faces(mesh), Mesh::size_type(4));
  }
}

/// Edges of more than two triangles in a soup of triangles.
std::size_t edges_of_more_than_two(const Polygons& triangles)
{
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for(const auto& t : triangles)
    for(std::size_t i = 0; i < 3; ++i)
      ++uses[std::minmax(t[i], t[(i + 1) % 3])];
  return std::size_t(std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second > 2; }));
}

/// Faces that share corners which are not neighbours in one of them (the primal of a
/// bar thinner than a cell, its parallel edge split by vertex 6): a fan from the first
/// corner of (4, 6, 2, 5, 0) took 4-2, an edge of the other faces, as a diagonal (an
/// edge of four triangles); the fan starts where its diagonals are free. And a
/// non-convex hexagon whose constrained triangulation takes a diagonal that is an edge
/// of the mesh: the fan of a corner that sees the others, with free diagonals.
void test_diagonals_that_are_edges()
{
  const std::vector<Point> bar{Point(0, 3, 0.2), Point(0, 1, 0.5), Point(0, 2, 0.5), Point(0, 1, 0.2),
                               Point(0, 2, 0.2), Point(0, 3, 0.5), Point(-0.075, 2, 0.5)};
  const Polygons bar_faces{{5, 2, 4, 0}, {4, 6, 2, 5, 0}, {3, 4, 2, 1}, {2, 6, 4, 3, 1}};
  Polygons polygons = bar_faces;
  RSR::internal::split_polygons(bar, polygons);
  CHECK_EQ(polygons.size(), std::size_t(10));
  CHECK_EQ(edges_of_more_than_two(polygons), std::size_t(0));
  // a non-convex hexagon (reflex corner 4) in z = 0, and a triangle above it on the two
  // ends of a diagonal its constrained triangulation takes: that diagonal is an edge
  const std::vector<Point> hexagon{Point(0, 0, 0), Point(2, -1, 0), Point(4, 0, 0), Point(4, 3, 0),
                                   Point(2, 2, 0), Point(0, 3, 0), Point(2, 1, 5)};
  const std::vector<std::size_t> outline{0, 1, 2, 3, 4, 5};
  Polygons alone{outline};
  RSR::internal::split_polygons(hexagon, alone);
  auto diagonals_of = [&](const Polygons& triangles) {
    std::set<std::pair<std::size_t, std::size_t>> diagonals;
    for(const auto& t : triangles)
      for(std::size_t i = 0; i < 3 && std::count(t.begin(), t.end(), std::size_t(6)) == 0; ++i) {
        const std::pair<std::size_t, std::size_t> e = std::minmax(t[i], t[(i + 1) % 3]);
        if(e.second < 6 && e.second - e.first != 1 && e != std::make_pair(std::size_t(0), std::size_t(5)))
          diagonals.insert(e);
      }
    return diagonals;
  };
  CHECK_EQ(alone.size(), std::size_t(4));
  const auto taken = *diagonals_of(alone).begin();
  Polygons with_edge{outline, {taken.second, taken.first, 6}};
  RSR::internal::split_polygons(hexagon, with_edge);
  CHECK_EQ(with_edge.size(), std::size_t(5));
  CHECK_EQ(diagonals_of(with_edge).count(taken), std::size_t(0));
  CHECK_EQ(edges_of_more_than_two(with_edge), std::size_t(0));
  // every triangle of the hexagon turns as it does (none folds over corner 4)
  using Point_2 = CGAL::Kernel_traits<Point>::Kernel::Point_2;
  for(const auto& t : with_edge)
    if(t[2] != 6 && t[0] != 6 && t[1] != 6)
      CHECK(CGAL::orientation(Point_2(hexagon[t[0]].x(), hexagon[t[0]].y()), Point_2(hexagon[t[1]].x(), hexagon[t[1]].y()),
                              Point_2(hexagon[t[2]].x(), hexagon[t[2]].y())) == CGAL::COUNTERCLOCKWISE);
}

/// The linear sort of the soup's edges gives the order of a comparison sort by (key,
/// corner): random soups of triangles to hexagons over few points (repeated keys, some
/// runs of more than two) with a hub named by many polygons (a run longer than the
/// insertion sort takes).
void test_sorted_polygon_edges()
{
  std::mt19937 random(7);
  for(int trial = 0; trial < 50; ++trial) {
    const std::size_t points = 2 + std::size_t(trial) * 3;
    Polygons polygons(200);
    for(auto& polygon : polygons) {
      polygon.resize(3 + random() % 4);
      for(std::size_t& v : polygon)
        v = random() % 3 == 0 ? points / 2 : random() % points;
    }
    const RSR::internal::Soup_corners corners(polygons);
    const auto edges = RSR::internal::sorted_polygon_edges(corners);
    auto expected = edges;
    std::sort(expected.begin(), expected.end());
    bool same = edges.size() == corners.size();
    for(std::size_t i = 0; same && i < edges.size(); ++i)
      same = edges[i].key == expected[i].key && edges[i].corner == expected[i].corner &&
             edges[i].forward == expected[i].forward;
    CHECK(same);
  }
}


/// The area of a triangle mesh's faces, each counted positive: a triangle that leaves
/// its polygon overlaps another one, and adds area the polygon does not have.
double unsigned_area(const Mesh& mesh)
{
  double area = 0;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    area += std::sqrt(CGAL::squared_area(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                         mesh.point(target(next(h, mesh), mesh))));
  }
  return area;
}

/// A closed prism of height 1 over the polygon `cap` (counterclockwise, in (u, v)),
/// as a soup of its two caps and its quadrilateral sides, standing along `axis`; and
/// its area.
double prism_soup(const std::vector<std::array<double, 2>>& cap, int axis, std::vector<Point>& points,
                  Polygons& polygons)
{
  const auto point = [axis](double u, double v, double w) { // turned so that w is along axis
    const std::array<double, 3> c{u, v, w};
    return Point(c[(5 - axis) % 3], c[(3 - axis) % 3], c[(4 - axis) % 3]);
  };
  const std::size_t n = cap.size();
  points.clear();
  polygons.assign(2, {});
  double area = 0;
  for(std::size_t i = 0; i < n; ++i) {
    points.push_back(point(cap[i][0], cap[i][1], 0));
    points.push_back(point(cap[i][0], cap[i][1], 1));
    polygons[0].push_back(2 * (n - 1 - i)); // the bottom cap, turned outward
    polygons[1].push_back(2 * i + 1);
    const std::size_t j = (i + 1) % n;
    polygons.push_back({2 * i, 2 * j, 2 * j + 1, 2 * i + 1});
    area += cap[i][0] * cap[j][1] - cap[j][0] * cap[i][1]; // twice the cap's signed area
    area += std::hypot(cap[j][0] - cap[i][0], cap[j][1] - cap[i][1]);
  }
  return area;
}

/// Polygons with reflex corners (an L, a ten-pointed star, a dart) split inside
/// themselves in whichever plane they lie: a fan from the first corner folded over the
/// reflex corners (hostile round 9, F1: the L-prism's area came out 14.53 for 14).
void test_non_convex_polygons_split_inside()
{
  std::vector<std::array<double, 2>> star;
  for(int i = 0; i < 10; ++i) {
    const double radius = i % 2 ? 1 : 2.5, angle = 2 * CGAL_PI * i / 10;
    star.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  const std::vector<std::vector<std::array<double, 2>>> caps{
      {{0, 1}, {0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 1}}, // an L whose first corner is next to the reflex one
      {{1, 1}, {0, 0}, {3, 0}, {3, 2}, {1, 2}, {0, 2}},
      star,
      {{1, 0}, {0, 10}, {-1, 0}, {0, 1}}}; // a dart: its shorter diagonal is outside it
  for(const auto& cap : caps)
    for(int axis = 0; axis < 3; ++axis) {
      std::vector<Point> points;
      Polygons polygons;
      const double area = prism_soup(cap, axis, points, polygons);
      Mesh mesh;
      const auto repairs = RSR::prepare_input(points, polygons, mesh, RSR::Input_repair::REFUSE);
      CHECK_EQ(repairs.triangulated_polygons, cap.size() + 2);
      CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh));
      CHECK(std::abs(unsigned_area(mesh) - area) <= 1e-12 * area);
    }
}

/// A quadrilateral that crosses itself and a polygon that does not lie in a plane go
/// on as before (a fan): no split stays inside them, and none may hang.
void test_polygons_crossing_themselves()
{
  std::vector<Point> points{Point(0, 0, 0), Point(1, 1, 0), Point(1, 0, 0), Point(0, 1, 0)};
  Polygons polygons{{0, 1, 2, 3}};
  Mesh mesh;
  RSR::prepare_input(points, polygons, mesh);
  CHECK_EQ(num_faces(mesh), Mesh::size_type(2));
  std::vector<Point> crown;
  Polygons crown_polygon(1);
  for(int i = 0; i < 12; ++i) {
    const double radius = i % 3 ? 1 : 0.3, angle = 2 * CGAL_PI * i / 12;
    crown.emplace_back(radius * std::cos(angle), radius * std::sin(angle), i % 2);
    crown_polygon[0].push_back(std::size_t(i));
  }
  RSR::prepare_input(crown, crown_polygon, mesh);
  CHECK_EQ(num_faces(mesh), Mesh::size_type(10));
}

} // namespace

int main(int argc, char** argv)
{
  test_diagonals_that_are_edges();
  if(argc < 2) {
    std::cerr << "usage: test_prepare_input MESH_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  test_same_mesh_as_cgal(argv[1]);
  test_vertex_of_huge_valence();
  test_quadrilaterals_around_a_vertex_of_valence_2();
  test_non_convex_quadrilateral_around_a_vertex_of_valence_2();
  test_sorted_polygon_edges();
  test_non_convex_polygons_split_inside();
  test_polygons_crossing_themselves();
  return report("test_prepare_input");
}
