// No folded quad leaves the pipeline (issue 39): `remesh()` with the command-line
// program's defaults, at a quarter of the input's vertices, on CGAL's sample meshes.
// The output is measured by the criterion: a quad is folded or non-convex when
// the min over its corners of (e_next x e_prev) . n / (|e_next| |e_prev|) is <= 0, n
// its unit vector-area normal.
// The normal maps read the normals averaged 8 times (`smooth_vertex_normals()`, as the
// program does), and also as computed on the smooth models and fandisk.
// With the position-normal map (n = 6) the untangling stage says how many faces it
// left folded (none) and non-convex (the same count); on the smooth meshes it leaves
// none, on fandisk's creases, where vertices are held on crease lines, at most as many
// as it found. Before the stage the relaxation left some on every one of them.
// With position, normal and colour bands (n = 9), refined_elephant had 129 (at the
// issue's filing) and has none.
// With the identity (n = 3), moving vertices left quads non-convex where faces bend
// over thin limbs (armadillo 4, man 11): the collapses and rotations after the moves
// remove them (on man, 2 are left without the doublets' dissolution), keeping all
// quads and the topology. No doublet (a vertex of valence 2) is left.
// argv[1]: the folder holding CGAL's sample meshes.
#include "test_support.h"

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Identity_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <cmath>

using namespace test;

namespace {

using Vector = K::Vector_3;

std::vector<Point> corners_of(const Mesh& m, Mesh::Face_index f)
{
  std::vector<Point> corners;
  for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
    corners.push_back(m.point(v));
  return corners;
}

// twice the vector area (the fan from the first corner)
Vector vector_area(const std::vector<Point>& c)
{
  Vector area = CGAL::NULL_VECTOR;
  for(std::size_t i = 1; i + 1 < c.size(); ++i)
    area = area + CGAL::cross_product(c[i] - c[0], c[i + 1] - c[0]);
  return area;
}

bool is_non_convex(const std::vector<Point>& c)
{
  const Vector area = vector_area(c);
  const double length = std::sqrt(area.squared_length());
  if(!(length > 0))
    return true;
  const std::size_t n = c.size();
  for(std::size_t i = 0; i < n; ++i) {
    const Vector next = c[(i + 1) % n] - c[i], prev = c[(i + n - 1) % n] - c[i];
    const double lengths = std::sqrt(next.squared_length() * prev.squared_length());
    if(!(lengths > 0) || !(CGAL::cross_product(next, prev) * area / (length * lengths) > 0))
      return true;
  }
  return false;
}

// the 1st percentile of the corner angles of all faces, in degrees (the issue's
// measure of shape)
double first_percentile_angle(const Mesh& m)
{
  std::vector<double> angles;
  for(auto f : faces(m)) {
    const std::vector<Point> c = corners_of(m, f);
    const std::size_t n = c.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Vector next = c[(i + 1) % n] - c[i], prev = c[(i + n - 1) % n] - c[i];
      const double lengths = std::sqrt(next.squared_length() * prev.squared_length());
      angles.push_back(lengths > 0 ? std::acos(std::clamp(next * prev / lengths, -1., 1.)) * 180 / CGAL_PI : 0);
    }
  }
  std::sort(angles.begin(), angles.end());
  return angles.empty() ? 0 : angles[angles.size() / 100];
}

long euler_characteristic(const Mesh& m)
{
  return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
}

enum class Map
{
  IDENTITY,
  POSITION_NORMAL,
  POSITION_NORMAL_COLOR // n = 9, with colour bands made on the input
};

template <class RangeMap>
RSR::Remesh_statistics remesh_a_quarter(const Mesh& input, Mesh& quads, const RangeMap& f, double diagonal)
{
  return RSR::remesh(input, quads,
                     RSR::parameters::range_map(f)
                         .grid_spacing(0.01 * diagonal)
                         .number_of_target_vertices(num_vertices(input) / 4)
                         .seeding_method(RSR::Seeding_method::COMPLETE_SCAN)
                         .check_topology(true)
                         .refine_around_defects(true)
                         .quad_collapse(true)
                         .number_of_relaxation_steps(3));
}

struct Measured
{
  RSR::Remesh_statistics stats;
  std::size_t vertices = 0, non_convex = 0; // the count
  double first_percentile_angle = 0;        // degrees
};

// `folds_may_stay`: a face may stay folded against its corners' normals (they vary at
// the scale of the input's facets).
// `normal_smoothing`: the rounds of `smooth_vertex_normals()` (the program's default).
Measured check_model(const std::string& folder, const std::string& name, bool smooth,
                     Map map = Map::POSITION_NORMAL, bool folds_may_stay = false, std::size_t normal_smoothing = 8)
{
  Mesh input;
  CHECK(CGAL::IO::read_polygon_mesh(folder + "/" + name + ".off", input));
  const double diagonal = bbox_diagonal(input);
  Mesh quads;
  RSR::Remesh_statistics stats;
  if(map == Map::IDENTITY) {
    stats = remesh_a_quarter(input, quads, RSR::Identity_range_map(get(CGAL::vertex_point, input)), diagonal);
  } else {
    auto normals = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), input);
    RSR::compute_vertex_normals(input, normals);
    if(normal_smoothing > 0)
      RSR::smooth_vertex_normals(input, normals, RSR::parameters::number_of_iterations(normal_smoothing));
    if(map == Map::POSITION_NORMAL) {
      const RSR::Position_normal_range_map f(get(CGAL::vertex_point, input), normals, 1.0, 0.1 * diagonal);
      stats = remesh_a_quarter(input, quads, f, diagonal);
    } else {
      // three smooth bands of each channel per diagonal, along each axis: the colour
      // varies everywhere (CGAL's sample meshes have none)
      auto colors = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), input);
      for(auto v : vertices(input)) {
        const Point& p = input.point(v);
        auto band = [&](double x) { return 0.5 + 0.5 * std::sin(6 * CGAL_PI * x / diagonal); };
        put(colors, v, std::array<double, 3>{{band(p.x()), band(p.y()), band(p.z())}});
      }
      const RSR::Position_normal_color_range_map f(get(CGAL::vertex_point, input), normals, colors, 1.0,
                                                   0.1 * diagonal, 0.1 * diagonal);
      stats = remesh_a_quarter(input, quads, f, diagonal);
    }
  }
  std::size_t non_convex = 0;
  for(auto face : faces(quads))
    non_convex += is_non_convex(corners_of(quads, face));
  std::cout << name << (map == Map::IDENTITY ? " (identity)" : map == Map::POSITION_NORMAL_COLOR ? " (n = 9)" : "")
            << (map != Map::IDENTITY && normal_smoothing == 0 ? " (normals not averaged)" : "") << ": " << num_faces(quads) << " faces, "
            << non_convex << " folded or non-convex (the stage: folded " << stats.untangle.folded_before << " -> "
            << stats.untangle.folded_after << ", non-convex " << stats.untangle.non_convex_before << " -> "
            << stats.untangle.non_convex_after << "; " << stats.untangle.moves << " moves in " << stats.untangle.rounds
            << " rounds, " << stats.untangle.collapses << " collapses, " << stats.untangle.rotations << " rotations, "
            << stats.untangle.moves_off_surface << " moves off the surface), "
            << stats.collapse.removed_doublets << " doublets dissolved" << std::endl;
  CHECK(num_faces(quads) > 0);
  CHECK(stats.untangle.non_convex_after <= stats.untangle.non_convex_before);
  std::size_t non_quads = 0; // the collapses and rotations make no face that is not a quad
  for(auto face : faces(quads))
    non_quads += degree(face, quads) != 4;
  CHECK_EQ(non_quads, stats.all_quads.non_quads_after);
  // no vertex inside the surface is left with two quads sharing two of its edges (a
  // doublet): the collapse dissolves them, rows of them one by one, and again after
  // its passes (bunny00 and fandisk, position-normal: 1 left each before). A closed
  // piece of two faces (every corner of valence 2, what is left of a limb thinner than
  // a cell) has no quad to dissolve into: the topology check counts it.
  auto in_two_face_piece = [&](Mesh::Vertex_index v) {
    for(auto f : CGAL::faces_around_target(halfedge(v, quads), quads))
      for(auto w : CGAL::vertices_around_face(halfedge(f, quads), quads))
        if(degree(w, quads) != 2)
          return false;
    return true;
  };
  std::size_t doublets = 0;
  for(auto v : vertices(quads))
    doublets += degree(v, quads) == 2 && !is_border(v, quads) && !in_two_face_piece(v);
  CHECK_EQ(doublets, std::size_t(0));
  if(stats.topology_preserved()) // ... and the topology
    CHECK_EQ(euler_characteristic(quads), euler_characteristic(input));
  if(smooth)
    CHECK_EQ(non_convex, std::size_t(0));
  const Measured measured{stats, num_vertices(quads), non_convex, first_percentile_angle(quads)};
  std::cout << "  1st-percentile corner angle " << measured.first_percentile_angle << " degrees" << std::endl;
  // the stage counts a face folded and not convex as folded
  CHECK(non_convex <= stats.untangle.non_convex_after + stats.untangle.folded_after);
  if(map == Map::IDENTITY || folds_may_stay)
    return measured; // a face may stay folded against its corners' normals across a thin limb, convex
  CHECK_EQ(stats.untangle.folded_after, std::size_t(0));
  // with no face folded, the library's non-convex faces are the issue's
  CHECK_EQ(stats.untangle.non_convex_after, non_convex);
  return measured;
}

// The squaring after the untangling (quads made squares at their corners, along the
// surface): the targets for the 1st-percentile corner angle, 50 degrees with
// the identity, 35 with the position-normal map. Before it, armadillo had 45.3 and man
// 39.8 with the identity, bunny00 21.5 with position and normal (the mean of the
// neighbours keeps the sheared quads of the normal map's cells sheared).
void check_shape(const Measured& measured, double least_first_percentile_angle)
{
  CHECK(measured.first_percentile_angle >= least_first_percentile_angle);
}

// man with the position-normal map: its normals vary at the scale of its facets, and
// the untangling leaves faces folded and a few non-convex where the primal lost its
// topology (fingers, toes). The last resort's operations go on after the moves have
// spent their tries, round after round: at most a tenth of the non-convex faces the
// stage found are left by the count (27 of 222 when the operations stopped with
// the tries, after one round; 5 before the untangling off the tangent planes, 2 now).
void check_operations_go_on(const std::string& folder)
{
  const Measured man = check_model(folder, "man", false, Map::POSITION_NORMAL, true, 0);
  CHECK(man.non_convex * 10 <= man.stats.untangle.non_convex_before);
  CHECK(man.stats.untangle.collapses + man.stats.untangle.rotations > 0);
  CHECK(man.stats.untangle.moves_off_surface > 0); // the run off the tangent planes too
}

// man with the position-normal map and its normals averaged as the program does: the
// steps of the normal between its facets gave closed loops and non-disk cells that the
// refinement around defects could not mend (its lenses passed their budget of twice
// the vertices: χ 2 -> 10, 3 components); averaged, the refinement keeps the topology.
// Where man's triangles fold over one another (dihedral angles up to 178 degrees), a
// quad whose corners are held on crease lines by the planes they sample stayed
// non-convex by the count (1 before the untangling off the tangent planes; the
// relaxation no longer makes a face convex in itself a dart either).
void check_man_keeps_its_topology(const std::string& folder)
{
  const Measured man = check_model(folder, "man", false, Map::POSITION_NORMAL, true);
  CHECK(man.stats.topology_preserved());
  CHECK_EQ(man.stats.primal.output_components, std::size_t(1)); // and χ 2: check_model()
  CHECK_EQ(man.non_convex, std::size_t(0));
}

// The last resort's connectivity changes follow the collapse's parameters: none without
// `quad_collapse`, no rotation without `do_flip` (armadillo made 2 before either).
void check_collapse_parameters(const std::string& folder)
{
  Mesh input;
  CHECK(CGAL::IO::read_polygon_mesh(folder + "/armadillo.off", input));
  const double diagonal = bbox_diagonal(input);
  const RSR::Identity_range_map f(get(CGAL::vertex_point, input));
  auto parameters = RSR::parameters::range_map(f)
                        .grid_spacing(0.01 * diagonal)
                        .number_of_target_vertices(num_vertices(input) / 4)
                        .number_of_relaxation_steps(3);
  Mesh quads;
  const auto without_rotations = RSR::remesh(input, quads, parameters.do_flip(false));
  CHECK_EQ(without_rotations.untangle.rotations, std::size_t(0));
  quads.clear();
  const auto without_collapse = RSR::remesh(input, quads, parameters.quad_collapse(false));
  CHECK_EQ(without_collapse.untangle.collapses + without_collapse.untangle.rotations, std::size_t(0));
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: test_untangling MESH_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  check_model(argv[1], "refined_elephant", true);
  check_shape(check_model(argv[1], "bunny00", true), 35);
  check_model(argv[1], "fandisk", false);
  // the normals as computed, the library's maps' default
  check_model(argv[1], "refined_elephant", true, Map::POSITION_NORMAL, false, 0);
  check_model(argv[1], "bunny00", true, Map::POSITION_NORMAL, false, 0);
  check_model(argv[1], "fandisk", false, Map::POSITION_NORMAL, false, 0);
  check_shape(check_model(argv[1], "armadillo", true, Map::IDENTITY), 50);
  check_shape(check_model(argv[1], "man", true, Map::IDENTITY), 50);
  check_model(argv[1], "refined_elephant", true, Map::POSITION_NORMAL_COLOR);
  check_operations_go_on(argv[1]);
  check_man_keeps_its_topology(argv[1]);
  check_collapse_parameters(argv[1]);
  return report("test_untangling");
}
