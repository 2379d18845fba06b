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

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: test_prepare_input MESH_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  test_same_mesh_as_cgal(argv[1]);
  test_vertex_of_huge_valence();
  test_quadrilaterals_around_a_vertex_of_valence_2();
  test_sorted_polygon_edges();
  return report("test_prepare_input");
}
