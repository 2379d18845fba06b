// The primal remesh on meshes generated in code: invariants, Euler characteristic,
// degenerate positions, dimensions 3 to 12, both kernels, Polyhedron_3, errors.
#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <CGAL/Range_space_remeshing/copy_in_spatial_order.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>

using namespace test;
namespace params = CGAL::parameters;
using RSR::parameters::range_map;
using RSR::parameters::grid_origin;


void test_euler_characteristic()
{
  struct Case { const char* name; Mesh mesh; long chi; double h; };
  std::vector<Case> cases;
  cases.push_back({"sphere", make_sphere(1.0, 4), 2, 0.1});
  cases.push_back({"ellipsoid", make_ellipsoid(1.5, 1.0, 0.6, 4), 2, 0.1});
  cases.push_back({"torus", make_torus(1.0, 0.4, 120, 60), 0, 0.1});
  cases.push_back({"genus 2", make_genus_2(3), -2, 0.1});
  for(Case& c : cases) {
    CHECK_EQ(euler_characteristic(c.mesh), c.chi);
    for(double h : {c.h, c.h / 2}) {
      Mesh out;
      const auto stats = remesh_and_check(c.mesh, out, params::grid_spacing(h));
      std::cout << c.name << " h=" << h << ": " << num_vertices(out) << " vertices, "
                << num_faces(out) << " faces, " << stats.digons << " digons" << std::endl;
      CHECK_EQ(euler_characteristic(out), c.chi);
      CHECK_EQ(number_of_components(out), std::size_t(1));
      CHECK(num_vertices(out) > 100);
    }
  }
}

void test_lattice_cube()
{
  // every input vertex lies on grid planes, every edge on grid edges or planes
  Mesh cube = make_lattice_cube(4);
  for(double h : {1.0, 2.0, 0.5}) {
    Mesh out;
    remesh_and_check(cube, out, params::grid_spacing(h));
    CHECK_EQ(euler_characteristic(out), 2L);
    CHECK_EQ(number_of_components(out), std::size_t(1));
  }
  // a 4x4x4 cube at h = 1: grid edges through the surface = 96 (perturbed lattice)
  Mesh out;
  remesh_and_check(cube, out, params::grid_spacing(1.0));
  CHECK_EQ(num_vertices(out), std::size_t(96));
}

void test_appended_coordinates()
{
  const Mesh sphere = make_sphere(1.0, 3, Point(0.013, -0.021, 0.007));
  Mesh reference;
  remesh_and_check(sphere, reference, params::grid_spacing(0.25));
  const std::string expected = fingerprint(reference);

  for(double constant : {2.0, 0.3, -1.0}) {
    Mesh out;
    auto f = appended<4>(sphere, [constant](const Point&, std::array<double, 4>& x) { x[3] = constant; });
    remesh_and_check(sphere, out, range_map(f).grid_spacing(0.25));
    CHECK(fingerprint(out) == expected);
  }
  // a constant coordinate before the others: same output too
  {
    Mesh out;
    auto f = appended<4>(sphere, [](const Point& p, std::array<double, 4>& x) {
      x = {{1.0, p.x(), p.y(), p.z()}};
    });
    remesh_and_check(sphere, out, range_map(f).grid_spacing(0.25));
    CHECK(fingerprint(out) == expected);
  }
  // a duplicated coordinate: the surface lies in the hyperplane x_3 = x_0
  {
    Mesh out;
    auto f = appended<4>(sphere, [](const Point& p, std::array<double, 4>& x) { x[3] = p.x(); });
    remesh_and_check(sphere, out, range_map(f).grid_spacing(0.25));
    CHECK_EQ(euler_characteristic(out), 2L);
    CHECK(num_vertices(out) >= num_vertices(reference));
  }
}

template <int D>
void test_dimension(const Mesh& torus)
{
  Mesh out;
  // f(p) = (x, y, z, then D-3 fixed generic linear combinations of x, y, z)
  auto f = appended<D>(torus, [](const Point& p, std::array<double, D>& x) {
    for(int q = 3; q < D; ++q)
      x[q] = (0.31 + 0.07 * q) * p.x() - (0.23 + 0.05 * q) * p.y() + (0.17 - 0.03 * q) * p.z();
  });
  const auto stats = remesh_and_check(torus, out, range_map(f).grid_spacing(0.15));
  std::cout << "D=" << D << ": " << num_vertices(out) << " vertices, " << stats.digons
            << " digons" << std::endl;
  CHECK_EQ(euler_characteristic(out), 0L);
  CHECK_EQ(number_of_components(out), std::size_t(1));
  if constexpr(D < 12)
    test_dimension<D + 1>(torus);
}

void test_kernels_and_graphs()
{
  const Mesh torus = make_torus(1.0, 0.35, 80, 40);
  Mesh epick_out, epeck_out;
  remesh_and_check(torus, epick_out, params::grid_spacing(0.1));
  using Epeck_traits = RSR::Range_space_traits<3, CGAL::Exact_predicates_exact_constructions_kernel>;
  remesh_and_check(torus, epeck_out, params::grid_spacing(0.1).geom_traits(Epeck_traits()));
  CHECK(fingerprint(epick_out) == fingerprint(epeck_out));

  // a lattice-aligned input, where the perturbation decides most predicates
  const Mesh cube = make_lattice_cube(3);
  Mesh cube_epick, cube_epeck;
  remesh_and_check(cube, cube_epick, params::grid_spacing(1.0));
  remesh_and_check(cube, cube_epeck, params::grid_spacing(1.0).geom_traits(Epeck_traits()));
  CHECK(fingerprint(cube_epick) == fingerprint(cube_epeck));

  // Polyhedron_3 in and out
  using Polyhedron = CGAL::Polyhedron_3<K>;
  Polyhedron poly_in, poly_out;
  CGAL::copy_face_graph(torus, poly_in);
  const auto stats = RSR::primal_remesh(poly_in, poly_out, params::grid_spacing(0.1));
  CHECK(CGAL::is_valid_polygon_mesh(poly_out));
  CHECK(CGAL::is_closed(poly_out));
  CHECK_EQ(num_vertices(poly_out), num_vertices(epick_out));
  CHECK_EQ(num_faces(poly_out), num_faces(epick_out));
  CHECK_EQ(stats.output_faces, num_faces(poly_out));
}

template <class F>
bool throws_remeshing_error(F f, const std::string& saying = "")
{
  try {
    f();
  } catch(const RSR::Remeshing_error& e) {
    std::cout << "  expected error: " << e.what() << std::endl;
    return std::string(e.what()).find(saying) != std::string::npos;
  }
  return false;
}

void test_determinism_and_seeding()
{
  const Mesh genus_2 = make_genus_2(3);
  Mesh a, b, seeded;
  remesh_and_check(genus_2, a, params::grid_spacing(0.13));
  remesh_and_check(genus_2, b, params::grid_spacing(0.13));
  CHECK(fingerprint(a) == fingerprint(b));
  const auto stats = remesh_and_check(
      genus_2, seeded, params::grid_spacing(0.13).seeding_method(RSR::Seeding_method::SEEDED));
  CHECK_EQ(num_vertices(seeded), num_vertices(a));
  CHECK_EQ(num_faces(seeded), num_faces(a));
  CHECK_EQ(stats.seeds, std::size_t(1));

  // On a finely tessellated input the seeded traversal maps a fraction of it.
  const Mesh fine = make_sphere(1.0, 6); // 40,962 vertices
  Mesh out;
  const auto fine_stats = remesh_and_check(
      fine, out, params::grid_spacing(0.25).seeding_method(RSR::Seeding_method::SEEDED));
  std::cout << "seeded: mapped " << fine_stats.mapped_vertices << " of "
            << num_vertices(fine) << " input vertices" << std::endl;
  CHECK(fine_stats.mapped_vertices * 3 < num_vertices(fine));
  CHECK_EQ(euler_characteristic(out), 2L);

  // Given seed faces, the traversal reads only what it reaches: a quad in another
  // component is never seen (the default search for one seed per component walks the
  // whole mesh, and refuses it).
  {
    Mesh sphere_and_quad = make_sphere(1.0, 3);
    const auto first_face = *faces(sphere_and_quad).begin();
    std::array<Mesh::Vertex_index, 4> q;
    for(int c = 0; c < 4; ++c)
      q[c] = sphere_and_quad.add_vertex(Point(5 + (c == 1 || c == 2), 5 + (c >= 2), 5));
    sphere_and_quad.add_face(q[0], q[1], q[2], q[3]);
    Mesh from_seed, whole_sphere;
    const std::vector<Mesh::Face_index> seeds(1, first_face);
    const auto seeded_stats = RSR::primal_remesh(
        sphere_and_quad, from_seed,
        RSR::parameters::seed_faces(seeds).grid_spacing(0.25).seeding_method(RSR::Seeding_method::SEEDED));
    remesh_and_check(make_sphere(1.0, 3), whole_sphere, params::grid_spacing(0.25));
    CHECK_EQ(num_vertices(from_seed), num_vertices(whole_sphere)); // (created in another order)
    CHECK_EQ(num_faces(from_seed), num_faces(whole_sphere));
    CHECK_EQ(euler_characteristic(from_seed), 2L);
    CHECK(seeded_stats.visited_faces < num_faces(sphere_and_quad));
    Mesh refused;
    CHECK(throws_remeshing_error([&] {
      RSR::primal_remesh(sphere_and_quad, refused,
                         params::grid_spacing(0.25).seeding_method(RSR::Seeding_method::SEEDED));
    }));
  }

  // a Surface_mesh with removed elements (indices beyond the live count) works
  {
    Mesh with_garbage; // a removed triangle first: every live index is shifted
    const auto u0 = with_garbage.add_vertex(Point(5, 5, 5));
    const auto u1 = with_garbage.add_vertex(Point(6, 5, 5));
    const auto u2 = with_garbage.add_vertex(Point(5, 6, 5));
    const auto dummy = with_garbage.add_face(u0, u1, u2);
    CGAL::Euler::remove_face(halfedge(dummy, with_garbage), with_garbage);
    CGAL::copy_face_graph(genus_2, with_garbage);
    CHECK(with_garbage.has_garbage());
    Mesh out;
    remesh_and_check(with_garbage, out, params::grid_spacing(0.13));
    CHECK(fingerprint(out) == fingerprint(a));
  }

  // the grid origin shifts the lattice
  Mesh shifted;
  remesh_and_check(fine, shifted, grid_origin(std::array<double, 3>{{0.1, 0.05, 0.0}}).grid_spacing(0.25));
  CHECK_EQ(euler_characteristic(shifted), 2L);
  CHECK(fingerprint(shifted) != fingerprint(out));
}

/// The tracer's arrays by input vertex or face (internal/Lazily_zeroed_array.h): small
/// ones come from calloc / malloc, large ones (32 MB and more) are mapped pages; both
/// must read zero until written, hold what is written, and move.
void test_lazily_zeroed_arrays()
{
  using RSR::internal::Lazily_zeroed_array;
  for(std::size_t n : {std::size_t(0), std::size_t(1000), std::size_t(3) << 20, std::size_t(10) << 20}) {
    Lazily_zeroed_array<std::uint32_t> a(n);
    CHECK_EQ(a.size(), n);
    bool all_zero = true, all_kept = true;
    for(std::size_t i = 0; i < n; i += 4093)
      all_zero = all_zero && a[i] == 0;
    for(std::size_t i = 0; i < n; i += 4093)
      a[i] = std::uint32_t(i + 1);
    Lazily_zeroed_array<std::uint32_t> b;
    b = std::move(a);
    for(std::size_t i = 0; i < n; i += 4093)
      all_kept = all_kept && b[i] == std::uint32_t(i + 1);
    CHECK(all_zero);
    CHECK(all_kept);
    CHECK(a.empty() && b.size() == n);
  }
  // On a large input (327,680 faces, 7.9 MB of face records) the seeded traversal gives
  // the complete scan's remesh. The second complete scan gets the memory the first one
  // freed, not fresh pages: it repeats itself exactly only if no entry of the arrays
  // left uninitialised is read before it is written.
  const Mesh finest = make_sphere(1.0, 7);
  Mesh complete, again, seeded;
  remesh_and_check(finest, complete, params::grid_spacing(0.2));
  remesh_and_check(finest, again, params::grid_spacing(0.2));
  const auto stats = remesh_and_check(finest, seeded,
                                      params::grid_spacing(0.2).seeding_method(RSR::Seeding_method::SEEDED));
  CHECK(fingerprint(complete) == fingerprint(again));
  CHECK_EQ(num_vertices(seeded), num_vertices(complete));
  CHECK_EQ(num_faces(seeded), num_faces(complete));
  CHECK_EQ(euler_characteristic(seeded), 2L);
  CHECK(stats.mapped_vertices * 3 < num_vertices(finest));
}

void test_errors()
{
  const Mesh sphere = make_sphere(1.0, 2);
  Mesh out;
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(Mesh(), out); }));
  for(double h : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::quiet_NaN()})
    CHECK(throws_remeshing_error([&] { RSR::primal_remesh(sphere, out, params::grid_spacing(h)); }));
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(sphere, out, params::grid_spacing(1e-12)); }));
  // The output size is estimated before it is built: refused with the estimate
  // whether the cap is small or the default (about 2e8 expected here; the scan
  // estimates once its bound passes a million vertices, long before the cap).
  const std::string refusal = "the output would have about";
  CHECK(throws_remeshing_error(
      [&] { RSR::primal_remesh(sphere, out, params::grid_spacing(0.01).maximum_number(1000)); }, refusal));
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(sphere, out, params::grid_spacing(3e-4)); }, refusal));
  // About 1.6e7 expected (6 pi / h^2 for the unit sphere): refused by the default cap,
  // which keeps the whole pipeline's memory within reach (the old 5e7 let it run out).
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(sphere, out, params::grid_spacing(1.1e-3)); }, refusal));
  // one face holding about 1e10 vertices: refused before its scan builds any
  Mesh one_triangle;
  one_triangle.add_face(one_triangle.add_vertex(Point(0, 0, 0)), one_triangle.add_vertex(Point(1, 0, 0)),
                        one_triangle.add_vertex(Point(0, 1, 1)));
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(one_triangle, out, params::grid_spacing(1e-5)); }, refusal));
  // one face across nearly 2^30 levels in each of three axes: more crossed levels than
  // a 32-bit count holds (it overflowed: UBSan's report in the sanitizer suite), still
  // refused before its scan
  const double far = double((1 << 29) - 2);
  Mesh huge_triangle;
  huge_triangle.add_face(huge_triangle.add_vertex(Point(-far, -far, -far)),
                         huge_triangle.add_vertex(Point(far, -far, far)), huge_triangle.add_vertex(Point(-far, far, far)));
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(huge_triangle, out, params::grid_spacing(1.0)); }, refusal));
  // a needle of a face along the same diagonal: nearly no area (a small estimate), but
  // 3 * 2^30 crossed levels, whose scan ran for minutes
  Mesh needle;
  needle.add_face(needle.add_vertex(Point(-far, -far, -far)), needle.add_vertex(Point(far, far, far)),
                  needle.add_vertex(Point(far, far - 1e-7, far)));
  for(const auto seeding : {RSR::Seeding_method::COMPLETE_SCAN, RSR::Seeding_method::SEEDED})
    CHECK(throws_remeshing_error(
        [&] { RSR::primal_remesh(needle, out, params::grid_spacing(1.0).seeding_method(seeding)); },
        "grid hyperplanes, more than the cap"));
  // of the kind a caller backs off from (a target search, a local refinement)
  RSR::Remeshing_error::Kind needle_kind = RSR::Remeshing_error::Kind::BAD_INPUT;
  try {
    RSR::primal_remesh(needle, out, params::grid_spacing(1.0));
  } catch(const RSR::Remeshing_error& e) {
    needle_kind = e.kind();
  }
  CHECK(needle_kind == RSR::Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  // A cap above the estimate (7,396 for 7,378 vertices) that the scan's bound reaches
  // on the way (after 2,902 vertices): the scan goes on after the estimate, to the
  // same output.
  Mesh uncapped, capped;
  const auto uncapped_stats = RSR::primal_remesh(sphere, uncapped, params::grid_spacing(0.05));
  RSR::primal_remesh(sphere, capped,
                     params::grid_spacing(0.05).maximum_number(3 * uncapped_stats.intersection_vertices / 2));
  CHECK(fingerprint(capped) == fingerprint(uncapped));
  auto nan_map = appended<4>(sphere, [](const Point& p, std::array<double, 4>& x) {
    x[3] = p.x() > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  });
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(sphere, out, range_map(nan_map)); }));
  Mesh quads;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                        Point(0, 1, 1), Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), quads);
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh(quads, out, params::grid_spacing(0.3)); }));
}

void test_sampled_geometry()
{
  // positions are on the input triangles, normals interpolate the input's
  const Mesh sphere = make_sphere(1.0, 4);
  Mesh out;
  auto normals = out.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  RSR::primal_remesh(sphere, out, params::grid_spacing(0.1), params::vertex_normal_map(normals));
  double worst_radius = 0, worst_alignment = 1;
  for(auto v : vertices(out)) {
    const K::Vector_3 p = out.point(v) - CGAL::ORIGIN;
    const double r = std::sqrt(p.squared_length());
    worst_radius = std::max(worst_radius, std::abs(r - 1.0));
    const K::Vector_3 n = normals[v];
    CHECK(std::abs(n.squared_length() - 1.0) < 1e-9);
    worst_alignment = std::min(worst_alignment, n * p / r);
  }
  std::cout << "sampled geometry: max |radius - 1| = " << worst_radius
            << ", min normal . radial = " << worst_alignment << std::endl;
  CHECK(worst_radius < 2e-3);    // chord error of the 5,120-triangle sphere
  CHECK(worst_alignment > 0.999);
}

void test_needle()
{
  // A long, thin tetrahedron across a hundred thousand cells: the candidate lattice
  // points of a face are enumerated column by column, not over its bounding box.
  Mesh needle;
  const Point a(0, 0, 0), b(1e5, 1e5, 1e5 + 0.5), c(0.05, 0, 0), d(0, 0.05, 0);
  CGAL::make_tetrahedron(a, b, c, d, needle);
  if(CGAL::Polygon_mesh_processing::volume(needle) < 0)
    CGAL::Polygon_mesh_processing::reverse_face_orientations(needle);
  Mesh out;
  const auto stats = remesh_and_check(needle, out, params::grid_spacing(1.0));
  std::cout << "needle: " << stats.output_vertices << " vertices in " << stats.time_total_ms
            << " ms" << std::endl;
  CHECK(stats.output_vertices > 0);
}

#if defined(CGAL_LINKED_WITH_TBB)
/// The parallel complete scan gives the sequential result, vertex numbering included.
template <class NP>
void check_parallel_is_sequential(const char* name, const Mesh& input, const NP& np)
{
  Mesh sequential, parallel;
  const RSR::Statistics s = RSR::primal_remesh<CGAL::Sequential_tag>(input, sequential, np);
  const RSR::Statistics p = RSR::primal_remesh<CGAL::Parallel_tag>(input, parallel, np);
  std::cout << "parallel scan, " << name << ": " << p.output_vertices << " vertices, "
            << (fingerprint(parallel) == fingerprint(sequential) ? "identical" : "DIFFERENT") << std::endl;
  CHECK(num_faces(parallel) > 0);
  CHECK(fingerprint(parallel) == fingerprint(sequential));
  bool same_points = num_vertices(parallel) == num_vertices(sequential);
  for(auto v : vertices(parallel))
    same_points = same_points && parallel.point(v) == sequential.point(v);
  CHECK(same_points);
  CHECK_EQ(p.mapped_vertices, s.mapped_vertices);
  CHECK_EQ(p.visited_faces, s.visited_faces);
  CHECK_EQ(p.uncrossed_border_cycles, s.uncrossed_border_cycles);
}

void test_parallel_scan()
{
  check_parallel_is_sequential("sphere", make_sphere(1.0, 6), params::grid_spacing(0.05));
  check_parallel_is_sequential("genus 2", make_genus_2(4), params::grid_spacing(0.07));
  check_parallel_is_sequential("lattice cube", make_lattice_cube(6), params::grid_spacing(1.0 / 3));
  Mesh open_sphere = make_sphere(1.0, 5); // a border: the boundary vertices come in order too
  std::vector<Mesh::Face_index> cap;
  for(auto f : faces(open_sphere))
    if(open_sphere.point(target(halfedge(f, open_sphere), open_sphere)).z() > 0.7)
      cap.push_back(f);
  for(auto f : cap)
    CGAL::Euler::remove_face(halfedge(f, open_sphere), open_sphere);
  open_sphere.collect_garbage();
  check_parallel_is_sequential("open sphere", open_sphere, params::grid_spacing(0.06));
  const Mesh torus = make_torus(1.0, 0.4, 120, 60);
  auto lifted = appended<5>(torus, [](const Point& p, std::array<double, 5>& x) {
    x[3] = std::sin(3 * p.x());
    x[4] = 0.5 * p.y() * p.z();
  });
  check_parallel_is_sequential("torus in R^5", torus, range_map(lifted).grid_spacing(0.08));
  // errors found on another thread reach the caller as on this one
  auto nan_map = appended<4>(torus, [](const Point& p, std::array<double, 4>& x) {
    x[3] = p.x() > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  });
  Mesh out;
  CHECK(throws_remeshing_error([&] { RSR::primal_remesh<CGAL::Parallel_tag>(torus, out, range_map(nan_map)); }));
}
#endif

/// Mean distance in the face numbering between faces that share an edge: about a third
/// of the faces for a random order, small for an order that follows the surface.
double mean_index_gap_across_edges(const Mesh& m)
{
  double sum = 0;
  std::size_t pairs = 0;
  for(auto e : edges(m)) {
    const auto h = halfedge(e, m);
    if(is_border_edge(h, m))
      continue;
    sum += std::abs(double(std::size_t(face(h, m))) - double(std::size_t(face(opposite(h, m), m))));
    ++pairs;
  }
  return sum / double(pairs);
}

/// The same surface as `m`, its vertices and faces numbered at random.
Mesh shuffled_copy(const Mesh& m, unsigned seed)
{
  std::mt19937 random(seed);
  std::vector<std::size_t> vertex_order(num_vertices(m));
  std::iota(vertex_order.begin(), vertex_order.end(), std::size_t(0));
  std::shuffle(vertex_order.begin(), vertex_order.end(), random);
  Mesh shuffled;
  std::vector<Mesh::Vertex_index> copy_of(num_vertices(m));
  for(std::size_t i : vertex_order)
    copy_of[i] = shuffled.add_vertex(m.point(Mesh::Vertex_index(std::uint32_t(i))));
  std::vector<Mesh::Face_index> face_order(faces(m).begin(), faces(m).end());
  std::shuffle(face_order.begin(), face_order.end(), random);
  for(auto f : face_order) {
    std::vector<Mesh::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      corners.push_back(copy_of[std::size_t(v)]);
    CHECK(CGAL::Euler::add_face(corners, shuffled) != Mesh::null_face());
  }
  return shuffled;
}

void test_copy_in_spatial_order()
{
  const Mesh shuffled = shuffled_copy(make_torus(1.0, 0.4, 80, 40), 7);
  Mesh ordered;
  std::vector<Mesh::Vertex_index> vertex_copy(num_vertices(shuffled));
  std::vector<Mesh::Face_index> face_copy(num_faces(shuffled));
  RSR::copy_in_spatial_order(shuffled, ordered,
                             params::vertex_to_vertex_map(CGAL::make_property_map(vertex_copy))
                                 .face_to_face_map(CGAL::make_property_map(face_copy)));
  CHECK(CGAL::is_valid_polygon_mesh(ordered));
  CHECK_EQ(num_vertices(ordered), num_vertices(shuffled));
  CHECK_EQ(num_faces(ordered), num_faces(shuffled));
  // the same points, and every face with the same corners in the same cyclic order
  for(auto v : vertices(shuffled))
    CHECK(ordered.point(vertex_copy[std::size_t(v)]) == shuffled.point(v));
  std::size_t faces_differing = 0;
  for(auto f : faces(shuffled)) {
    std::vector<Mesh::Vertex_index> expected, found;
    for(auto v : CGAL::vertices_around_face(halfedge(f, shuffled), shuffled))
      expected.push_back(vertex_copy[std::size_t(v)]);
    for(auto v : CGAL::vertices_around_face(halfedge(face_copy[std::size_t(f)], ordered), ordered))
      found.push_back(v);
    const auto first = std::find(found.begin(), found.end(), expected.front());
    if(first == found.end()) {
      ++faces_differing;
      continue;
    }
    std::rotate(found.begin(), first, found.end());
    faces_differing += found != expected;
  }
  CHECK_EQ(faces_differing, std::size_t(0));
  // neighbours near each other in memory: the point of the copy
  const double gap_before = mean_index_gap_across_edges(shuffled), gap_after = mean_index_gap_across_edges(ordered);
  std::cout << "copy_in_spatial_order: mean index gap across edges " << gap_before << " -> " << gap_after
            << std::endl;
  CHECK(gap_after < 0.1 * gap_before);
  // the remesh does not depend on the order
  Mesh a, b;
  remesh_and_check(shuffled, a, params::grid_spacing(0.1));
  remesh_and_check(ordered, b, params::grid_spacing(0.1));
  CHECK_EQ(num_vertices(a), num_vertices(b));
  CHECK_EQ(num_faces(a), num_faces(b));
  // into another graph type
  CGAL::Polyhedron_3<K> polyhedron;
  RSR::copy_in_spatial_order(shuffled, polyhedron);
  CHECK(CGAL::is_valid_polygon_mesh(polyhedron));
  CHECK_EQ(num_faces(polyhedron), num_faces(shuffled));
  // a NaN point: refused before anything is copied
  Mesh with_nan = shuffled, untouched;
  with_nan.point(*vertices(with_nan).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK(throws_remeshing_error([&] { RSR::copy_in_spatial_order(with_nan, untouched); }));
  CHECK_EQ(num_vertices(untouched), std::size_t(0));
}

/// The closed box [lo, hi], twelve triangles, oriented outwards.
Mesh make_box(const Point& lo, const Point& hi)
{
  Mesh m;
  std::array<Mesh::Vertex_index, 8> v;
  for(int i = 0; i < 8; ++i)
    v[i] = m.add_vertex(Point((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z()));
  for(const auto& q : std::array<std::array<int, 4>, 6>{{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}}) {
    m.add_face(v[q[0]], v[q[1]], v[q[2]]);
    m.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  return m;
}

// A bar thinner than a cell, halved lengthwise by the grid plane x = 0 and crossed by
// the planes y = 1, 2, 3: the faces of the cells on either side of x = 0 share their
// four corners, and the two arcs where y = 2 cuts the bar join the same two vertices
// (camel.off's tail, man.off's fingers: written as they were, they read back as an edge
// of four faces). One is split by a vertex on its arc, on the bar's surface and on its
// side of x = 0, inside the cell of its faces; a finer grid has no parallel edges.
void test_parallel_edges_around_a_thin_bar()
{
  const Mesh bar = make_box(Point(-0.15, 0.5, 0.2), Point(0.15, 3.5, 0.5));
  CHECK(CGAL::is_closed(bar) && CGAL::Polygon_mesh_processing::is_outward_oriented(bar));
  Mesh out;
  const auto stats = remesh_and_check(bar, out, params::grid_spacing(1.0));
  CHECK_EQ(stats.split_parallel_edges, std::size_t(1));
  CHECK_EQ(stats.parallel_edges, std::size_t(0));
  CHECK_EQ(stats.intersection_vertices + 1, num_vertices(out));
  CHECK_EQ(euler_characteristic(out), 2L);
  std::size_t on_arc = 0;
  for(auto v : vertices(out)) {
    if(CGAL::halfedges_around_target(v, out).size() != 2)
      continue;
    const Point& p = out.point(v);
    // on the plane y = 2, on a side of the bar (|x| = 0.15, z inside) or on its top or
    // bottom (z = 0.2 or 0.5, x off the plane x = 0)
    const bool on_side = std::abs(std::abs(p.x()) - 0.15) < 1e-12 && p.z() > 0.2 && p.z() < 0.5;
    const bool on_cap = (std::abs(p.z() - 0.2) < 1e-12 || std::abs(p.z() - 0.5) < 1e-12) && std::abs(p.x()) > 1e-3 &&
                        std::abs(p.x()) <= 0.15;
    on_arc += (std::abs(p.y() - 2) < 1e-12 && (on_side || on_cap)) ? 1 : 0;
  }
  CHECK_EQ(on_arc, std::size_t(1));
  // the dual's primal keeps them (its dual undoes them), as before
  Mesh quads;
  const auto kept = RSR::remesh(bar, quads, params::grid_spacing(1.0));
  CHECK_EQ(kept.primal.parallel_edges, std::size_t(1));
  CHECK_EQ(kept.primal.split_parallel_edges, std::size_t(0));
  Mesh fine;
  const auto fine_stats = remesh_and_check(bar, fine, params::grid_spacing(0.1));
  CHECK_EQ(fine_stats.parallel_edges + fine_stats.split_parallel_edges, std::size_t(0));
  CHECK_EQ(euler_characteristic(fine), 2L);
}

int main()
{
  test_parallel_edges_around_a_thin_bar();
  test_sampled_geometry();
  test_needle();
  test_euler_characteristic();
  test_lattice_cube();
  test_appended_coordinates();
  test_dimension<3>(make_torus(1.0, 0.4, 90, 45));
  test_kernels_and_graphs();
  test_determinism_and_seeding();
  test_lazily_zeroed_arrays();
  test_errors();
  test_copy_in_spatial_order();
#if defined(CGAL_LINKED_WITH_TBB)
  test_parallel_scan();
#else
  std::cout << "TBB not linked: the parallel scan is not tested" << std::endl;
#endif
  return report("test_primal_remesh");
}
