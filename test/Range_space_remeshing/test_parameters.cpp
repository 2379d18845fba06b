// The public interface around the engines: named parameters chained in any order,
// the default cell size, number_of_target_vertices, the progress visitor and
// cancellation, the kinds of Remeshing_error.
// argv[1]: the folder holding CGAL's elephant.off.
#include "test_support.h"

#include <CGAL/Range_space_remeshing/Identity_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/copy_in_spatial_order.h>
#include <CGAL/Range_space_remeshing/internal/Cell_size.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace test;

namespace {

using Call = std::pair<RSR::Remeshing_stage, double>;

/// Whether `run()` throws a `Remeshing_error` of kind `kind`.
template <class Run>
bool throws_kind(const Run& run, RSR::Remeshing_error::Kind kind)
{
  try {
    run();
  } catch(const RSR::Remeshing_error& e) {
    return e.kind() == kind;
  }
  return false;
}

long genus_of(const Mesh& m) { return (2 - euler_characteristic(m)) / 2; }

/// Both chains of the issue, in different orders, give what the same values give
/// written with CGAL's own packs.
void test_chains(const Mesh& sphere)
{
  const auto vpm = get(CGAL::vertex_point, sphere);
  const auto f = RSR::make_position_normal_range_map(sphere, 1.0, 0.2);
  Mesh a, b, c;
  RSR::remesh(sphere, a,
              RSR::parameters::grid_spacing(0.15).range_map(f).preserve_topology(true).vertex_point_map(vpm));
  RSR::remesh(sphere, b,
              RSR::parameters::vertex_point_map(vpm)
                  .dual_placement(RSR::Dual_placement::QEM)
                  .range_map(f)
                  .preserve_topology(true)
                  .grid_spacing(0.15));
  RSR::remesh(sphere, c, RSR::parameters::range_map(f).grid_spacing(0.15).preserve_topology(true));
  CHECK(num_faces(a) > 0);
  CHECK_EQ(fingerprint(a), fingerprint(b));
  CHECK_EQ(fingerprint(a), fingerprint(c));
  // a CGAL pack is read too, and a chain of the package's is a CGAL pack for CGAL
  Mesh d;
  RSR::remesh(sphere, d, CGAL::parameters::grid_spacing(0.15).vertex_point_map(vpm));
  Mesh e;
  RSR::remesh(sphere, e, RSR::parameters::grid_spacing(0.15));
  CHECK_EQ(fingerprint(d), fingerprint(e));
  // the iteration counts have one name each
  Mesh collapsed = a;
  RSR::collapse_quads(collapsed, RSR::parameters::number_of_collapse_passes(1).do_flip(false));
  RSR::relax_on_tangent_planes(collapsed, RSR::parameters::number_of_relaxation_steps(2));
  CHECK(CGAL::is_valid_polygon_mesh(collapsed));
}

/// Without a cell size, 1% of the mapped bounding box's diagonal: the elephant keeps
/// its genus and gets thousands of quads (a cell of 1 gave 3 quads and genus 0).
void test_default_cell_size(const Mesh& elephant)
{
  Mesh quads;
  const RSR::Remesh_statistics stats = RSR::remesh(elephant, quads);
  std::cout << "elephant, defaults: " << num_faces(quads) << " quads, genus " << genus_of(quads) << ", cell size "
            << stats.primal.cell_size << std::endl;
  CHECK(CGAL::is_valid_polygon_mesh(quads));
  CHECK(num_faces(quads) > 2000);
  CHECK_EQ(genus_of(quads), genus_of(elephant));
  CHECK(std::abs(stats.primal.cell_size - RSR::default_relative_cell_size * bbox_diagonal(elephant)) <
        1e-12 * bbox_diagonal(elephant));
  // the default follows the map: twice the map, twice the cell
  const auto vpm = get(CGAL::vertex_point, elephant);
  const auto doubled = RSR::make_position_normal_range_map(elephant, 2.0, 0.0);
  Mesh primal;
  const RSR::Statistics s = RSR::primal_remesh(elephant, primal, RSR::parameters::range_map(doubled));
  CHECK(std::abs(s.cell_size - 2 * stats.primal.cell_size) < 1e-9 * s.cell_size);
  (void)vpm;
  // a box whose sides (2e308) and diagonal are beyond doubles: 1% of the diagonal is not
  // (it was refused as a box "without extent")
  Mesh huge = make_sphere(1e308, 2);
  Mesh huge_quads;
  const RSR::Remesh_statistics at_huge = RSR::remesh(huge, huge_quads);
  std::cout << "sphere of radius 1e308, defaults: " << num_faces(huge_quads) << " quads, cell size "
            << at_huge.primal.cell_size << std::endl;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(huge);
  long double squares = 0; // long double: its range holds the squares of 2e308
  for(int i = 0; i < 3; ++i)
    squares += ((long double)(box.max(i)) - box.min(i)) * ((long double)(box.max(i)) - box.min(i));
  const double expected = double(RSR::default_relative_cell_size * std::sqrt(squares));
  CHECK(std::abs(at_huge.primal.cell_size - expected) < 1e-12 * expected);
  CHECK(num_faces(huge_quads) > 100 && CGAL::is_valid_polygon_mesh(huge_quads));
}

// A count that jumps across the target (bunny00 at n = 9 and a quarter of its
// vertices: 11,349 at one cell size, 8,429 at 3 % more; target 9,426): only sizes in a
// narrow band give it. The secant steps went back and forth over the jump until the
// runs ran out; kept inside the bracket, they find the band.
void test_target_across_a_jump()
{
  std::vector<double> tried;
  auto run = [&](double h) {
    tried.push_back(h);
    const double factor = h < 0.99 ? 1.25 : h < 0.995 ? 1.0 : 0.8;
    return std::size_t(10000 / (h * h) * factor);
  };
  const double h = RSR::internal::search_cell_size(2.0, 10000, run, false);
  std::cout << "target across a jump: " << tried.size() << " runs, cell size " << h << std::endl;
  CHECK(h >= 0.99 && h < 0.995);
  CHECK(tried.size() <= std::size_t(RSR::internal::maximum_target_runs));
}

// Where the search starts: the projected areas of a unit square in the plane z = 0
// are 1 (on xy) and 0, so 100 cells of 0.1 cover it; a square without area, or one
// whose areas overflow, gives no size; a grid_spacing within a factor 2 of the
// estimate is kept, one further off is not.
void test_first_cell_size()
{
  auto square = [](double side, double z_of_x) {
    Mesh m;
    const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(side, 0, z_of_x * side)),
               c = m.add_vertex(Point(side, side, z_of_x * side)), d = m.add_vertex(Point(0, side, 0));
    m.add_face(a, b, c);
    m.add_face(a, c, d);
    return m;
  };
  const Mesh unit = square(1, 0);
  const RSR::Identity_range_map f(get(CGAL::vertex_point, unit));
  CHECK(std::abs(RSR::internal::cell_size_for_count(unit, f, 100) - 0.1) < 1e-12);
  Mesh flat = unit; // all four corners on a line
  for(auto v : vertices(flat))
    flat.point(v) = Point(flat.point(v).x() + flat.point(v).y(), 0, 0);
  CHECK_EQ(RSR::internal::cell_size_for_count(flat, RSR::Identity_range_map(get(CGAL::vertex_point, flat)), 100), 0.);
  const Mesh huge = square(1e200, 0);
  CHECK_EQ(RSR::internal::cell_size_for_count(huge, RSR::Identity_range_map(get(CGAL::vertex_point, huge)), 100), 0.);
  CHECK_EQ(RSR::internal::first_cell_size_for_count(unit, RSR::parameters::grid_spacing(0.15), 100), 0.15);
  CHECK(std::abs(RSR::internal::first_cell_size_for_count(unit, RSR::parameters::grid_spacing(0.5), 100) - 0.1) <
        1e-12);
  CHECK_EQ(RSR::internal::first_cell_size_for_count(
               unit, RSR::parameters::grid_spacing(0.5).seeding_method(RSR::Seeding_method::SEEDED), 100),
           0.5);
}

void test_target_vertices(const Mesh& elephant)
{
  for(std::size_t target : {1500, 6000}) {
    Mesh quads;
    const auto stats = RSR::remesh(elephant, quads, RSR::parameters::number_of_target_vertices(target));
    std::cout << "target " << target << ": " << num_vertices(quads) << " vertices at cell size "
              << stats.primal.cell_size << std::endl;
    CHECK(std::abs(double(num_vertices(quads)) - double(target)) <= 0.1 * double(target));
    CHECK(CGAL::is_valid_polygon_mesh(quads));
  }
  Mesh primal;
  RSR::primal_remesh(elephant, primal, RSR::parameters::number_of_target_vertices(std::size_t(4000)));
  CHECK(std::abs(double(num_vertices(primal)) - 4000.) <= 400.);
  // A target just below the cap (which bounds the primal, about 1.2 times the dual
  // here): the search steps to a finer size the cap refuses, and must come back between
  // it and the last size that ran (it doubled away from it, and went back to it, until
  // the runs ran out: "no cell size tried gives 3000 ... (the last gave 750)").
  for(std::size_t cap : {3300, 3500}) {
    Mesh near_cap;
    const auto stats = RSR::remesh(elephant, near_cap, RSR::parameters::number_of_target_vertices(std::size_t(3000))
                                                           .maximum_number(cap));
    std::cout << "target 3000, cap " << cap << ": " << num_vertices(near_cap) << " vertices at cell size "
              << stats.primal.cell_size << std::endl;
    CHECK(std::abs(double(num_vertices(near_cap)) - 3000.) <= 300.);
    CHECK(stats.primal.intersection_vertices <= cap);
  }
  // a cap below what the target needs: refused, and said so
  Mesh above_cap;
  CHECK(throws_kind([&] { RSR::remesh(elephant, above_cap, RSR::parameters::number_of_target_vertices(std::size_t(3000))
                                                                .maximum_number(std::size_t(3100))); },
                    RSR::Remeshing_error::Kind::TARGET_NOT_REACHED));
  // a count no cell size gives: told, not guessed
  Mesh tiny;
  CHECK(throws_kind([&] { RSR::remesh(elephant, tiny, RSR::parameters::number_of_target_vertices(std::size_t(3))); },
                    RSR::Remeshing_error::Kind::TARGET_NOT_REACHED));
}

/// The visitor hears every stage, in order, with fractions in [0, 1], on this thread.
void test_progress(const Mesh& elephant)
{
  std::vector<Call> calls;
  Mesh quads;
  RSR::remesh(elephant, quads, RSR::parameters::check_topology(true).progress_visitor([&](RSR::Remeshing_stage s, double f) {
    calls.emplace_back(s, f);
    return true;
  }));
  CHECK(calls.size() >= 7);
  bool ordered = true, in_range = true;
  std::vector<int> seen(7, 0);
  for(std::size_t i = 0; i < calls.size(); ++i) {
    in_range = in_range && calls[i].second >= 0 && calls[i].second <= 1;
    if(i > 0)
      ordered = ordered && calls[i - 1].first <= calls[i].first;
    seen[int(calls[i].first)] = 1;
  }
  CHECK(ordered);
  CHECK(in_range);
  for(int stage = 0; stage < 7; ++stage)
    CHECK_EQ(seen[stage], 1);
  // the same output with and without a visitor
  Mesh plain;
  RSR::remesh(elephant, plain, RSR::parameters::check_topology(true));
  CHECK_EQ(fingerprint(plain), fingerprint(quads));
}

/// Cancelled in any stage, or halfway: Remeshing_cancelled, and the output is empty
/// with its property maps still usable.
void test_cancel(const Mesh& elephant)
{
  std::size_t total = 0;
  {
    Mesh quads;
    RSR::remesh(elephant, quads, RSR::parameters::progress_visitor([&](RSR::Remeshing_stage, double) {
      ++total;
      return true;
    }));
  }
  for(int stage = 0; stage <= int(RSR::Remeshing_stage::RELAXATION); ++stage) {
    if(stage == int(RSR::Remeshing_stage::TOPOLOGY_CHECK))
      continue; // not run here: see below
    Mesh quads = elephant; // not empty before: emptied all the same
    auto colors = quads.add_property_map<Mesh::Vertex_index, int>("v:mark", 7).first;
    bool cancelled = false;
    try {
      RSR::remesh(elephant, quads, RSR::parameters::progress_visitor([&](RSR::Remeshing_stage s, double) {
        return int(s) != stage;
      }));
    } catch(const RSR::Remeshing_cancelled& e) {
      cancelled = e.kind() == RSR::Remeshing_error::Kind::CANCELLED;
    }
    CHECK(cancelled);
    CHECK_EQ(num_vertices(quads), Mesh::size_type(0));
    CHECK_EQ(num_faces(quads), Mesh::size_type(0));
    const auto v = quads.add_vertex(Point(0, 0, 0)); // the caller's map still works
    CHECK_EQ(colors[v], 7);
  }
  // halfway through the calls of a whole run, with the check and the target search
  std::size_t calls = 0;
  Mesh quads;
  bool cancelled = false;
  try {
    RSR::remesh(elephant, quads,
                RSR::parameters::check_topology(true).progress_visitor([&](RSR::Remeshing_stage, double) {
                  return ++calls < total / 2;
                }));
  } catch(const RSR::Remeshing_cancelled&) {
    cancelled = true;
  }
  CHECK(cancelled);
  CHECK_EQ(calls, total / 2);
  CHECK_EQ(num_faces(quads), Mesh::size_type(0));
  // the primal alone
  Mesh primal;
  cancelled = false;
  try {
    RSR::primal_remesh(elephant, primal,
                       RSR::parameters::check_topology(true).progress_visitor(
                           [](RSR::Remeshing_stage s, double) { return s != RSR::Remeshing_stage::TOPOLOGY_CHECK; }));
  } catch(const RSR::Remeshing_cancelled&) {
    cancelled = true;
  }
  CHECK(cancelled);
  CHECK_EQ(num_vertices(primal), Mesh::size_type(0));
  // the in-place stages: the collapse leaves a valid mesh, the relaxation an unchanged one
  Mesh dual;
  RSR::remesh(elephant, dual, RSR::parameters::quad_collapse(false).number_of_relaxation_steps(0));
  const auto stop_at_once = RSR::parameters::progress_visitor([](RSR::Remeshing_stage, double) { return false; });
  Mesh collapsed = dual;
  CHECK(throws_kind([&] { RSR::collapse_quads(collapsed, stop_at_once); }, RSR::Remeshing_error::Kind::CANCELLED));
  CHECK(CGAL::is_valid_polygon_mesh(collapsed));
  Mesh relaxed = dual;
  CHECK(throws_kind([&] { RSR::relax_on_tangent_planes(relaxed, stop_at_once); },
                    RSR::Remeshing_error::Kind::CANCELLED));
  CHECK_EQ(fingerprint(relaxed), fingerprint(dual));
  Mesh dualized;
  Mesh primal_again;
  RSR::primal_remesh(elephant, primal_again);
  CHECK(throws_kind([&] { RSR::dualize(primal_again, dualized, stop_at_once); },
                    RSR::Remeshing_error::Kind::CANCELLED));
  CHECK_EQ(num_vertices(dualized), Mesh::size_type(0));
}

void test_error_kinds(const Mesh& sphere)
{
  using Kind = RSR::Remeshing_error::Kind;
  Mesh out;
  CHECK(throws_kind([&] { RSR::remesh(sphere, out, RSR::parameters::grid_spacing(-1.0)); }, Kind::BAD_PARAMETER));
  CHECK(throws_kind([&] { RSR::remesh(Mesh(), out); }, Kind::BAD_INPUT));
  CHECK(throws_kind([&] { RSR::primal_remesh(sphere, out, RSR::parameters::grid_spacing(1e-3).maximum_number(1000)); },
                    Kind::OUTPUT_TOO_LARGE));
  CHECK(throws_kind(
            [&] {
              RSR::primal_remesh(sphere, out,
                                 RSR::parameters::preserve_topology(true).seeding_method(RSR::Seeding_method::SEEDED));
            },
            Kind::BAD_PARAMETER));
}

/// A mesh far from the origin (a scan in georeferenced coordinates): with the default
/// grid origin, 5e9 cells lie between it and the mesh, beyond the lattice's 2^29; the
/// origin moves next to the mesh, on the same lattice, so that the far sphere gives
/// the near one's remesh. A grid origin given that far is refused.
void test_far_from_origin()
{
  using Kind = RSR::Remeshing_error::Kind;
  const double offset = 1e8;
  const Mesh near = make_sphere(1.0, 3);
  const Mesh far = make_sphere(1.0, 3, Point(offset, offset, offset));
  const auto np = RSR::parameters::grid_spacing(0.02);
  Mesh near_out, far_out;
  RSR::primal_remesh(near, near_out, np);
  bool refused = false;
  try {
    RSR::primal_remesh(far, far_out, np);
  } catch(const RSR::Remeshing_error& error) {
    std::cout << "far sphere refused: " << error.what() << std::endl;
    refused = true;
  }
  CHECK(!refused);
  const double n_near = double(num_vertices(near_out)), n_far = double(num_vertices(far_out));
  std::cout << "sphere at the origin: " << n_near << " primal vertices; at 1e8: " << n_far << std::endl;
  CHECK(n_near > 1000 && std::abs(n_far - n_near) <= 0.01 * n_near);
  CHECK(CGAL::is_valid_polygon_mesh(far_out));
  double off_sphere = 0;
  for(auto v : vertices(far_out)) {
    const Point& p = far_out.point(v);
    const double r = std::sqrt(CGAL::square(p.x() - offset) + CGAL::square(p.y() - offset) + CGAL::square(p.z() - offset));
    off_sphere = (std::max)(off_sphere, std::abs(r - 1));
  }
  CHECK(off_sphere < 0.01); // the input's flat faces are within 0.01 of the sphere
  Mesh quads;
  RSR::remesh(far, quads);
  CHECK(num_faces(quads) > 100);
  const std::array<double, 3> origin = {{0, 0, 0}};
  CHECK(throws_kind([&] { RSR::primal_remesh(far, far_out, np.grid_origin(origin)); }, Kind::OUTPUT_TOO_LARGE));
  // where doubles no longer resolve a cell (a unit sphere at 1e15, cell 0.05: coordinates
  // 0.125 apart; a sphere 1e-12 across at 1e3, its default cell 3e-14, coordinates 1e-13
  // apart), the cells cannot bound the faces: refused, with the way out
  const Mesh farther = make_sphere(1.0, 3, Point(1e15, 1e15, 1e15));
  CHECK(throws_kind([&] { RSR::primal_remesh(farther, far_out, RSR::parameters::grid_spacing(0.05)); },
                    Kind::BAD_INPUT));
  const Mesh speck = make_sphere(1e-12, 2, Point(1e3, 1e3, 1e3));
  CHECK(throws_kind([&] { RSR::remesh(speck, quads); }, Kind::BAD_INPUT));
  const std::array<double, 3> far_origin = {{1e15, 0, 0}};
  CHECK(throws_kind([&] { RSR::primal_remesh(near, near_out, np.grid_origin(far_origin)); }, Kind::BAD_PARAMETER));
}

/// preserve_topology with a part far too small for the cap (a sphere 1e-5 across beside
/// a unit one, crossed by two grid planes: a piece the primal drops; and beside it, on
/// no grid plane: a lost component): refused after the first run, from the part's
/// extent, not after the refinements up to the cap (11 runs, about half a minute).
void test_hopeless_refinement()
{
  using Kind = RSR::Remeshing_error::Kind;
  for(const Point& centre : {Point(3.0131, 0, 0), Point(3.0131, 0.0137, 0.0213)}) {
    Mesh two = make_sphere(1.0, 3);
    CGAL::copy_face_graph(make_sphere(1e-5, 2, centre), two);
    std::size_t runs = 0; // entries into the scan: one per run
    bool in_scan = false;
    auto count_runs = [&](RSR::Remeshing_stage stage, double) {
      const bool scan = stage == RSR::Remeshing_stage::SCAN;
      runs += scan && !in_scan;
      in_scan = scan;
      return true;
    };
    Mesh out;
    CHECK(throws_kind([&] {
      RSR::primal_remesh(two, out, RSR::parameters::grid_spacing(0.05).preserve_topology(true).maximum_number(1000000)
                                       .progress_visitor(count_runs));
    }, Kind::TOPOLOGY_NOT_PRESERVED));
    std::cout << "hopeless refinement at (" << centre << "): " << runs << " runs" << std::endl;
    CHECK(runs <= 1);
  }
}

/// Counts out of their domain are refused before any work (the visitor is never called):
/// a negative count converted to an unsigned one, or a target the cap forbids, would
/// otherwise start a search that cannot end well.
void test_bad_counts(const Mesh& sphere)
{
  using Kind = RSR::Remeshing_error::Kind;
  namespace P = RSR::parameters;
  int calls = 0;
  const auto count_calls = [&calls](RSR::Remeshing_stage, double) { return ++calls > 0; };
  Mesh out;
  const auto refused = [&](const auto& run) {
    calls = 0;
    const bool bad_parameter = throws_kind(run, Kind::BAD_PARAMETER);
    return bad_parameter && calls == 0;
  };
  CHECK(refused([&] { RSR::remesh(sphere, out, P::number_of_target_vertices(-5).progress_visitor(count_calls)); }));
  CHECK(refused([&] { RSR::remesh(sphere, out, P::number_of_target_vertices(2.5).progress_visitor(count_calls)); }));
  CHECK(refused([&] { RSR::remesh(sphere, out, P::number_of_target_vertices(100000000).progress_visitor(count_calls)); }));
  CHECK(refused([&] {
    RSR::primal_remesh(sphere, out, P::maximum_number(1000).number_of_target_vertices(5000).progress_visitor(count_calls));
  }));
  CHECK(refused([&] { RSR::primal_remesh(sphere, out, P::maximum_number(-1).progress_visitor(count_calls)); }));
  CHECK(refused([&] { RSR::remesh(sphere, out, P::number_of_relaxation_steps(-1).progress_visitor(count_calls)); }));
  CHECK(refused([&] { RSR::remesh(sphere, out, P::number_of_collapse_passes(-1).progress_visitor(count_calls)); }));
  // a target at the cap is allowed
  Mesh at_cap;
  RSR::remesh(sphere, at_cap, P::maximum_number(100000).number_of_target_vertices(500));
  CHECK(num_faces(at_cap) > 0);

  Mesh quads;
  RSR::remesh(sphere, quads, P::number_of_relaxation_steps(0));
  const Mesh before = quads;
  CHECK(refused([&] { RSR::collapse_quads(quads, P::number_of_collapse_passes(-2).progress_visitor(count_calls)); }));
  CHECK(refused([&] { RSR::relax_on_tangent_planes(quads, P::number_of_relaxation_steps(-1).progress_visitor(count_calls)); }));
  CHECK_EQ(num_vertices(quads), num_vertices(before));
  CHECK(std::equal(quads.vertices().begin(), quads.vertices().end(), before.vertices().begin(),
                   [&](auto v, auto w) { return quads.point(v) == before.point(w); }));
}

/// An output that is the input is refused, and the mesh is left as it was: the output is
/// emptied before the input is read.
void test_same_mesh(const Mesh& sphere)
{
  using Kind = RSR::Remeshing_error::Kind;
  Mesh mesh = sphere;
  CHECK(throws_kind([&] { RSR::remesh(mesh, mesh); }, Kind::BAD_PARAMETER));
  CHECK(throws_kind([&] { RSR::primal_remesh(mesh, mesh); }, Kind::BAD_PARAMETER));
  CHECK(throws_kind([&] { RSR::copy_in_spatial_order(mesh, mesh); }, Kind::BAD_PARAMETER));
  CHECK_EQ(num_faces(mesh), num_faces(sphere));
  CHECK_EQ(num_vertices(mesh), num_vertices(sphere));
  Mesh primal;
  RSR::primal_remesh(sphere, primal);
  const auto primal_faces = num_faces(primal);
  CHECK(throws_kind([&] { RSR::dualize(primal, primal); }, Kind::BAD_PARAMETER));
  CHECK_EQ(num_faces(primal), primal_faces);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: test_parameters MESH_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  Mesh elephant;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(argv[1]) + "/elephant.off", elephant));
  const Mesh sphere = make_sphere(1.0, 3);
  test_chains(sphere);
  test_default_cell_size(elephant);
  test_target_across_a_jump();
  test_first_cell_size();
  test_target_vertices(elephant);
  test_progress(elephant);
  test_cancel(elephant);
  test_error_kinds(sphere);
  test_far_from_origin();
  test_hopeless_refinement();
  test_bad_counts(sphere);
  test_same_mesh(sphere);
  return report("test_parameters");
}
