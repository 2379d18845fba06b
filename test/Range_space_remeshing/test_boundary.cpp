// Surfaces with boundary (section 7 of the paper): meshes generated in code (disk,
// open cylinder, planar squares, a single triangle, a strip) and CGAL's open meshes,
// through the primal remesh and the dual pipeline.
// Usage: test_boundary [directory of CGAL's sample meshes]
#include "test_support.h"

#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/OFF.h>

#include <algorithm>
#include <limits>
#include <random>

using namespace test;
namespace params = CGAL::parameters;

// ------------------------------------------------------------------ open meshes

/// Builds a mesh from a grid of (rows + 1) x (columns + 1) points, each cell split
/// in two triangles; `wrap` joins the last column to the first (a cylinder).
template <class Position>
Mesh make_grid_mesh(int rows, int columns, bool wrap, Position position)
{
  Mesh m;
  const int stored_columns = wrap ? columns : columns + 1;
  std::vector<Mesh::Vertex_index> v;
  for(int r = 0; r <= rows; ++r)
    for(int c = 0; c < stored_columns; ++c)
      v.push_back(m.add_vertex(position(r, c)));
  auto at = [&](int r, int c) { return v[r * stored_columns + (c % stored_columns)]; };
  for(int r = 0; r < rows; ++r)
    for(int c = 0; c < columns; ++c) {
      m.add_face(at(r, c), at(r, c + 1), at(r + 1, c + 1));
      m.add_face(at(r, c), at(r + 1, c + 1), at(r + 1, c));
    }
  return m;
}

/// Square [0, size]^2 x {z}, n x n cells.
Mesh make_square(int n, double size, double z)
{
  return make_grid_mesh(n, n, false, [&](int r, int c) { return Point(size * c / n, size * r / n, z); });
}

/// Open cylinder of radius r and height `height` around the z axis, tilted so that
/// its two border circles cross the grid planes in general position.
Mesh make_open_cylinder(double radius, double height, int around, int along)
{
  return make_grid_mesh(along, around, true, [&](int r, int c) {
    const double a = 2 * CGAL_PI * c / around, z = height * r / along - height / 2;
    const double x = radius * std::cos(a), y = radius * std::sin(a);
    return Point(x, 0.96 * y - 0.28 * z, 0.28 * y + 0.96 * z);
  });
}

/// Disk of radius r: a centre and rings of triangles, slightly domed.
Mesh make_disk(double radius, int rings, int sectors)
{
  Mesh m;
  const auto centre = m.add_vertex(Point(0, 0, 0.1 * radius));
  std::vector<std::vector<Mesh::Vertex_index>> ring(rings + 1);
  for(int r = 1; r <= rings; ++r)
    for(int s = 0; s < sectors; ++s) {
      const double rho = radius * r / rings, a = 2 * CGAL_PI * (s + 0.5 * r) / sectors;
      const double z = 0.1 * radius * (1 - (rho / radius) * (rho / radius));
      ring[r].push_back(m.add_vertex(Point(rho * std::cos(a), rho * std::sin(a), z)));
    }
  for(int s = 0; s < sectors; ++s)
    m.add_face(centre, ring[1][s], ring[1][(s + 1) % sectors]);
  for(int r = 1; r < rings; ++r)
    for(int s = 0; s < sectors; ++s) {
      const int t = (s + 1) % sectors;
      m.add_face(ring[r][s], ring[r + 1][s], ring[r + 1][t]);
      m.add_face(ring[r][s], ring[r + 1][t], ring[r][t]);
    }
  return m;
}

// ------------------------------------------------------------------ border distance

using Segment = std::pair<Point, Point>;

std::vector<Segment> border_segments(const Mesh& m)
{
  std::vector<Segment> segments;
  for(auto h : halfedges(m))
    if(is_border(h, m))
      segments.emplace_back(m.point(source(h, m)), m.point(target(h, m)));
  return segments;
}

double distance_to_segments(const Point& p, const std::vector<Segment>& segments)
{
  double best = std::numeric_limits<double>::infinity();
  for(const Segment& s : segments)
    best = std::min(best, CGAL::squared_distance(p, K::Segment_3(s.first, s.second)));
  return std::sqrt(best);
}

/// Two-sided Hausdorff distance between the border polylines of two meshes,
/// sampled at 16 points per edge.
double border_hausdorff(const Mesh& a, const Mesh& b)
{
  const auto sa = border_segments(a), sb = border_segments(b);
  double d = 0;
  for(const auto& [from, to] : {std::make_pair(&sa, &sb), std::make_pair(&sb, &sa)})
    for(const Segment& s : *from)
      for(int i = 0; i <= 16; ++i)
        d = std::max(d, distance_to_segments(s.first + (s.second - s.first) * (i / 16.), *to));
  return d;
}

// ------------------------------------------------------------------ primal

struct Open_case
{
  std::string name;
  Mesh mesh;
  double h;
};

/// Primal remesh: invariants, border cycles, and the output border within a cell
/// diagonal of the input border (each output border edge is a chord of the input
/// border between two consecutive crossings, so both lie in one cell).
void check_primal(const Open_case& c, RSR::Seeding_method seeding)
{
  Mesh out;
  const auto stats = remesh_and_check(c.mesh, out, params::grid_spacing(c.h).seeding_method(seeding));
  const double hausdorff = border_hausdorff(c.mesh, out) / c.h;
  std::cout << c.name << (seeding == RSR::Seeding_method::SEEDED ? " (seeded)" : "") << " h=" << c.h
            << ": " << num_vertices(out) << " vertices, " << num_faces(out) << " faces, "
            << number_of_border_cycles(out) << " border cycles (input "
            << number_of_border_cycles(c.mesh) << ", uncrossed " << stats.uncrossed_border_cycles
            << "), digons " << stats.digons << " + " << stats.boundary_digons
            << " on the border, corners " << stats.boundary_corners << ", border Hausdorff "
            << hausdorff << " h" << std::endl;
  CHECK(num_faces(out) > 0);
  CHECK_EQ(stats.dropped_pieces, std::size_t(0));
  // each hole inside one cell is covered by a face
  CHECK_EQ(number_of_border_cycles(out), number_of_border_cycles(c.mesh) - stats.uncrossed_border_cycles);
  CHECK_EQ(euler_characteristic(out), euler_characteristic(c.mesh) + long(stats.uncrossed_border_cycles));
  CHECK(hausdorff <= std::sqrt(3.));
}

// ------------------------------------------------------------------ dual pipeline

using Vector = K::Vector_3;

std::vector<Point> border_points(const Mesh& m)
{
  std::vector<Point> points;
  for(auto v : vertices(m))
    if(CGAL::is_border(v, m))
      points.push_back(m.point(v));
  std::sort(points.begin(), points.end());
  return points;
}

std::size_t non_quads(const Mesh& m)
{
  std::size_t n = 0;
  for(auto f : faces(m))
    n += degree(f, m) != 4;
  return n;
}

/// Dual, collapse, relaxation: all quads, the input's border cycles, border vertices
/// never moved by the collapse, and the border kept within a cell of the input's.
void check_dual_pipeline(const Open_case& c)
{
  Mesh primal;
  auto normals = primal.add_property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  const auto primal_stats = RSR::primal_remesh(c.mesh, primal, params::grid_spacing(c.h),
                                               params::vertex_normal_map(normals));
  Mesh quads;
  auto planes = quads.add_property_map<Mesh::Vertex_index, RSR::Tangent_planes>("v:planes").first;
  auto dual_normals = quads.add_property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  const auto dual = RSR::dualize(primal, quads, RSR::parameters::dual_placement(RSR::Dual_placement::QEM).vertex_normal_map(normals),
                                 RSR::parameters::vertex_tangent_planes_map(planes).vertex_normal_map(dual_normals));
  const std::size_t cycles = number_of_border_cycles(c.mesh) - primal_stats.uncrossed_border_cycles;
  CHECK(CGAL::is_valid_polygon_mesh(quads));
  // all quads, but where a pair of parallel edges was undone by joining its two faces
  // (one face with more corners each, so that the dual can be stored in a file)
  CHECK(non_quads(quads) <= dual.joined_parallel_edges);
  CHECK_EQ(dual.parallel_edges, std::size_t(0));
  CHECK_EQ(dual.dropped_pieces, std::size_t(0));
  CHECK_EQ(number_of_border_cycles(quads), cycles);
  CHECK_EQ(euler_characteristic(quads), euler_characteristic(primal));
  const double dual_border = border_hausdorff(c.mesh, quads) / c.h;

  const auto fixed_border = border_points(quads);
  // a mesh from elsewhere need not keep its border vertices' halfedges on the border
  // (a collapse around such a vertex once left it pointing at a removed halfedge)
  for(auto v : vertices(quads))
    for(auto h : CGAL::halfedges_around_target(halfedge(v, quads), quads))
      if(!CGAL::is_border(source(h, quads), quads)) { // from inside: the edge a collapse can remove
        quads.set_halfedge(v, h);
        break;
      }
  const auto collapse = RSR::collapse_quads(
      quads, RSR::parameters::vertex_tangent_planes_map(planes).vertex_normal_map(dual_normals));
  CHECK(CGAL::is_valid_polygon_mesh(quads));
  CHECK(non_quads(quads) <= dual.joined_parallel_edges);
  CHECK(border_points(quads) == fixed_border);
  CHECK_EQ(number_of_border_cycles(quads), cycles);
  // parallel edges come from primal faces sharing two edges (coarse cells), the dual
  // undoes them, and the collapse must not add any
  CHECK_EQ(RSR::internal::number_of_parallel_edges(quads), std::size_t(0));

  RSR::relax_on_tangent_planes(quads, RSR::parameters::vertex_tangent_planes_map(planes).vertex_normal_map(dual_normals));
  const double relaxed_border = border_hausdorff(c.mesh, quads) / c.h;
  std::size_t regular = 0, inner = 0;
  for(auto v : vertices(quads))
    if(!CGAL::is_border(v, quads)) {
      ++inner;
      regular += degree(v, quads) == 4;
    }
  std::cout << c.name << " dual: " << num_vertices(quads) << " vertices, " << num_faces(quads)
            << " faces (" << non_quads(quads) << " not quads, " << dual.joined_parallel_edges
            << " parallel edges joined, " << dual.removed_pinches << " pinches removed), "
            << collapse.collapsed_quads << " collapsed, inner valence 4: "
            << 100. * regular / inner << " %, border Hausdorff dual " << dual_border
            << " h, relaxed " << relaxed_border << " h" << std::endl;
  // the dual border runs through the middles of primal border edges, themselves
  // chords of the input border within one cell
  CHECK(dual_border <= std::sqrt(3.));
  CHECK(relaxed_border <= std::sqrt(3.));
}

/// The relaxation of an open mesh it did not produce (no tangent planes): a jittered
/// square grid. Border vertices must slide along the square's sides only (a corner
/// stays, it is where two sides meet), and the grid must even out.
void test_relax_open_square()
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const int n = 12;
  Mesh m = make_grid_mesh(n, n, false, [&](int r, int c) {
    const bool border_row = r == 0 || r == n, border_column = c == 0 || c == n;
    const double x = border_column ? c : c + jitter(rng), y = border_row ? r : r + jitter(rng);
    return Point(x / n, y / n, 0.);
  });
  auto spread = [](const Mesh& mesh) {
    double shortest = 1e9, longest = 0;
    for(auto e : edges(mesh)) {
      const double l = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
      shortest = std::min(shortest, l);
      longest = std::max(longest, l);
    }
    return longest / shortest;
  };
  const double before = spread(m);
  RSR::relax_on_tangent_planes(m, RSR::parameters::number_of_relaxation_steps(10));
  const double after = spread(m);
  std::cout << "open square relaxed: edge-length ratio " << before << " -> " << after << std::endl;
  CHECK(after < before);
  for(auto v : vertices(m)) {
    const Point& p = m.point(v);
    CHECK(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1 && p.z() == 0);
    if(CGAL::is_border(v, m))
      CHECK(p.x() == 0 || p.x() == 1 || p.y() == 0 || p.y() == 1);
  }
  for(const Point& corner : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)}) {
    bool kept = false;
    for(auto v : vertices(m))
      kept = kept || m.point(v) == corner;
    CHECK(kept);
  }
}

std::vector<Open_case> generated_cases()
{
  std::vector<Open_case> cases;
  cases.push_back({"disk", make_disk(1.0, 30, 90), 0.1});
  cases.push_back({"open cylinder", make_open_cylinder(0.5, 2.0, 90, 60), 0.1});
  cases.push_back({"square off the lattice", make_square(17, 1.0, 0.013), 0.07});
  // every vertex on grid planes: x and y multiples of h, z = 0 exactly
  cases.push_back({"square in a grid plane", make_square(10, 1.0, 0.0), 0.1});
  cases.push_back({"coarse square, fine grid", make_square(1, 1.0, 0.3), 0.05});
  return cases;
}

void test_generated(RSR::Seeding_method seeding)
{
  for(const Open_case& c : generated_cases()) {
    check_primal(c, seeding);
    if(seeding == RSR::Seeding_method::COMPLETE_SCAN)
      check_dual_pipeline(c);
  }
}

/// A single triangle and a one-triangle-wide strip are all border: arcs go from
/// border to border, faces may have no interior vertex at all.
void test_all_border()
{
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(Point(0, 0, 0)), triangle.add_vertex(Point(1, 0.1, 0.2)),
                    triangle.add_vertex(Point(0.3, 0.9, 0.5)));
  Mesh strip = make_grid_mesh(1, 40, false, [](int r, int c) { return Point(0.05 * c, 0.03 * r, 0.01 * c); });
  for(const Mesh* m : {&triangle, &strip})
    for(auto seeding : {RSR::Seeding_method::COMPLETE_SCAN, RSR::Seeding_method::SEEDED}) {
      Mesh out;
      const auto stats = remesh_and_check(*m, out, params::grid_spacing(0.1).seeding_method(seeding));
      std::cout << "all border: " << num_faces(*m) << " triangles -> " << num_vertices(out)
                << " vertices, " << num_faces(out) << " faces" << std::endl;
      CHECK(num_faces(out) > 1);
      CHECK_EQ(number_of_border_cycles(out), std::size_t(1));
      CHECK_EQ(euler_characteristic(out), 1L);
      CHECK_EQ(stats.uncrossed_border_cycles, std::size_t(0));
    }
  check_dual_pipeline({"triangle", triangle, 0.1});
  check_dual_pipeline({"strip", strip, 0.1});
}

/// A small disk that one hyperplane crosses: two boundary vertices joined by an arc
/// and by two boundary edges. The output is one triangle: the input vertex where
/// the border turns becomes a corner, and the digon on the other side is merged.
void test_disk_crossed_once()
{
  Mesh disk = make_disk(0.2, 4, 12);
  for(auto v : vertices(disk))
    disk.point(v) = disk.point(v) + K::Vector_3(0.03, 0.5, 0.5); // only x = 0 crosses it
  for(auto seeding : {RSR::Seeding_method::COMPLETE_SCAN, RSR::Seeding_method::SEEDED}) {
    Mesh out;
    const auto stats = remesh_and_check(disk, out, params::grid_spacing(1.0).seeding_method(seeding));
    CHECK_EQ(stats.boundary_corners, std::size_t(1));
    CHECK_EQ(stats.boundary_digons, std::size_t(1));
    CHECK_EQ(num_faces(out), std::size_t(1));
    CHECK_EQ(num_vertices(out), std::size_t(3));
    CHECK_EQ(number_of_border_cycles(out), std::size_t(1));
    // its vertices are all on the border with valence 2: no dual face, no dual
    Mesh quads;
    const auto dual = RSR::dualize(out, quads);
    CHECK_EQ(dual.dropped_pieces, std::size_t(1));
    CHECK_EQ(num_faces(quads), std::size_t(0));
    CHECK_EQ(num_vertices(quads), std::size_t(0));
  }
}

/// Two quads side by side: the border has two vertices of valence 3, so two chains
/// only; one is cut at a valence-2 vertex, whose dual face is a quad with a corner at
/// the vertex itself, so that the dual border cycle has four edges, on the primal's.
void test_dual_of_two_quads()
{
  Mesh two;
  std::vector<Mesh::Vertex_index> v;
  for(const auto& [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}})
    v.push_back(two.add_vertex(Point(x, y, 0)));
  two.add_face(v[0], v[1], v[4], v[5]);
  two.add_face(v[1], v[2], v[3], v[4]);
  Mesh quads;
  const auto dual = RSR::dualize(two, quads);
  CHECK(CGAL::is_valid_polygon_mesh(quads));
  CHECK_EQ(dual.quads, std::size_t(3));
  CHECK_EQ(dual.non_quads, std::size_t(0));
  CHECK_EQ(num_vertices(quads), std::size_t(6));
  CHECK_EQ(number_of_border_cycles(quads), std::size_t(1));
  CHECK_EQ(euler_characteristic(quads), 1L);
  // the dual border lies on the primal's: its four vertices (three chains', the
  // corner) are on the primal square's border, the faces' dual vertices inside
  std::size_t on_primal_border = 0, on_dual_border = 0;
  for(auto w : vertices(quads)) {
    const Point& p = quads.point(w);
    const bool on_border = p.y() == 0 || p.y() == 1 || p.x() == 0 || p.x() == 2;
    on_primal_border += on_border;
    on_dual_border += bool(CGAL::is_border(w, quads));
    CHECK_EQ(on_border, bool(CGAL::is_border(w, quads)));
  }
  CHECK_EQ(on_primal_border, std::size_t(4));
  CHECK_EQ(on_dual_border, std::size_t(4));
}

/// A hole inside one cell has no boundary vertex: the output covers it, and the
/// complete scan says so.
void test_uncrossed_hole()
{
  Mesh m = make_square(10, 1.0, 0.01);
  // remove the two triangles of [0.4, 0.5]^2: a hole inside the grid cell [0.3, 0.6]^2
  std::vector<Mesh::Face_index> doomed;
  for(auto f : faces(m)) {
    const auto c = CGAL::Polygon_mesh_processing::face_bbox(f, m);
    if(c.xmin() > 0.39 && c.xmax() < 0.51 && c.ymin() > 0.39 && c.ymax() < 0.51)
      doomed.push_back(f);
  }
  CHECK_EQ(doomed.size(), std::size_t(2));
  for(auto f : doomed)
    CGAL::Euler::remove_face(halfedge(f, m), m);
  m.collect_garbage();
  CHECK_EQ(number_of_border_cycles(m), std::size_t(2));
  Mesh out;
  // cells of 0.3 with the origin at 0: [0.3, 0.6] holds the hole
  const auto stats = remesh_and_check(m, out, params::grid_spacing(0.3));
  CHECK_EQ(stats.uncrossed_border_cycles, std::size_t(1));
  CHECK_EQ(number_of_border_cycles(out), std::size_t(1));
  // at a finer grid, a hyperplane crosses the hole: it is kept
  Mesh fine;
  const auto fine_stats = remesh_and_check(m, fine, params::grid_spacing(0.045));
  CHECK_EQ(fine_stats.uncrossed_border_cycles, std::size_t(0));
  CHECK_EQ(number_of_border_cycles(fine), std::size_t(2));
}

/// Border vertices where two fans of faces meet: one vertex, two border gaps (what a
/// face-list file cannot tell from a non-manifold vertex).
std::size_t pinched_vertices(const Mesh& m)
{
  std::vector<Mesh::Halfedge_index> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(m, std::back_inserter(pinched));
  return pinched.size();
}

/// A face between two border cycles of three edges (as coarse cells leave around a
/// small hole): each cycle has two chains, so the dual cuts it at its vertex of valence
/// 2, and both those vertices are corners of the same face. The dual border once went
/// through that face's dual vertex at both cuts: a pinched vertex, and a file with a
/// non-manifold vertex (elephant-with-holes.off at --cell-size 0.04 to 0.1).
void test_face_between_two_short_holes()
{
  Mesh primal;
  std::vector<Mesh::Vertex_index> grid; // 4 x 4 points, 3 x 3 squares
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i)
      grid.push_back(primal.add_vertex(Point(i, j, 0.1 * i * j)));
  auto at = [&](int i, int j) { return grid[4 * j + i]; };
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i)
      if(i != 1 || j != 1)
        CHECK(primal.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)) != Mesh::null_face());
  // the middle square, with a corner pushed in from its lower and its upper edge: two
  // holes of three edges, each with one vertex of valence 2, both in this face
  const Point x(1.5, 1.2, 0.2), y(1.5, 1.8, 0.3);
  const std::vector<Mesh::Vertex_index> middle = {at(1, 1), primal.add_vertex(x), at(2, 1),
                                                  at(2, 2), primal.add_vertex(y), at(1, 2)};
  CHECK(primal.add_face(middle) != Mesh::null_face());
  CHECK(CGAL::is_valid_polygon_mesh(primal));
  CHECK_EQ(number_of_border_cycles(primal), std::size_t(3));

  Mesh quads;
  const auto dual = RSR::dualize(primal, quads);
  CHECK(CGAL::is_valid_polygon_mesh(quads));
  CHECK_EQ(pinched_vertices(quads), std::size_t(0));
  CHECK_EQ(number_of_border_cycles(quads), std::size_t(3));
  CHECK_EQ(euler_characteristic(quads), euler_characteristic(primal));
  CHECK_EQ(dual.dropped_pieces, std::size_t(0));
  // the cut vertices are corners of the dual border: it stays on the primal's
  for(const Point& cut : {x, y})
    CHECK(std::count_if(vertices(quads).begin(), vertices(quads).end(), [&](Mesh::Vertex_index v) {
            return quads.point(v) == cut && CGAL::is_border(v, quads);
          }) == 1);
  // written and read back as a soup: a polygon mesh, with as many faces
  std::stringstream file;
  CHECK(CGAL::IO::write_OFF(file, quads, CGAL::parameters::stream_precision(17)));
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  CHECK(CGAL::IO::read_OFF(file, points, polygons));
  CHECK_EQ(polygons.size(), num_faces(quads));
  CHECK(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons));
}

void test_cgal_meshes(const std::string& directory)
{
  for(const std::string name : {"elephant-with-holes", "mech-holes-shark"}) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(directory + "/" + name + ".off", m)) {
      std::cerr << "cannot read " << name << std::endl;
      ++failures;
      continue;
    }
    for(double fraction : {0.02, 0.01}) {
      const Open_case c{name, m, fraction * bbox_diagonal(m)};
      check_primal(c, RSR::Seeding_method::COMPLETE_SCAN);
      check_dual_pipeline(c);
    }
    // coarse cells leave small holes of three edges, several around one face
    for(double fraction : {0.04, 0.05, 0.06, 0.07, 0.08, 0.1}) {
      Mesh quads;
      RSR::remesh(m, quads, params::grid_spacing(fraction * bbox_diagonal(m)));
      CHECK(CGAL::is_valid_polygon_mesh(quads));
      CHECK_EQ(pinched_vertices(quads), std::size_t(0));
    }
  }
}

int main(int argc, char** argv)
{
  test_generated(RSR::Seeding_method::COMPLETE_SCAN);
  test_generated(RSR::Seeding_method::SEEDED);
  test_all_border();
  test_disk_crossed_once();
  test_dual_of_two_quads();
  test_relax_open_square();
  test_uncrossed_hole();
  test_face_between_two_short_holes();
  if(argc > 1)
    test_cgal_meshes(argv[1]);
  return report("test_boundary");
}
