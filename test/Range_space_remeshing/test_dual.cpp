// The dual quad mesh and the relaxation: validity, all quads, Euler characteristic,
// orientation, distance to the input for both placements, no shrinking.
#include "test_support.h"

#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <random>

using namespace test;
namespace params = CGAL::parameters;
using Vector = K::Vector_3;

struct Dual_run
{
  Mesh quads;
  RSR::Dual_statistics stats;
};

Dual_run dual_of(const Mesh& primal, Mesh::Property_map<Mesh::Vertex_index, Vector> normals,
                 RSR::Dual_placement placement)
{
  Dual_run run;
  auto planes = run.quads.add_property_map<Mesh::Vertex_index, RSR::Tangent_planes>("v:planes").first;
  auto dual_normals = run.quads.add_property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  run.stats = RSR::dualize(primal, run.quads,
                           RSR::parameters::dual_placement(placement, params::vertex_normal_map(normals)),
                           RSR::parameters::vertex_tangent_planes_map(planes, params::vertex_normal_map(dual_normals)));
  CHECK(CGAL::is_valid_polygon_mesh(run.quads));
  CHECK(CGAL::is_closed(run.quads));
  CHECK_EQ(run.stats.non_quads, std::size_t(0));
  CHECK_EQ(run.stats.parallel_edges, std::size_t(0));
  CHECK_EQ(run.stats.dropped_pieces, std::size_t(0));
  std::size_t quads = 0;
  for(auto f : faces(run.quads))
    quads += (degree(f, run.quads) == 4);
  CHECK_EQ(quads, num_faces(run.quads));
  CHECK_EQ(euler_characteristic(run.quads), euler_characteristic(primal));
  return run;
}

void check_input(const std::string& name, const Mesh& input, double relative_cell_size)
{
  const double h = relative_cell_size * bbox_diagonal(input);
  Mesh checked_primal;
  remesh_and_check(input, checked_primal, params::grid_spacing(h));
  Mesh primal;
  auto normals = primal.add_property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  RSR::primal_remesh(input, primal, params::grid_spacing(h), params::vertex_normal_map(normals));
  CHECK(fingerprint(primal) == fingerprint(checked_primal));

  Dual_run qem = dual_of(primal, normals, RSR::Dual_placement::QEM);
  Dual_run average = dual_of(primal, normals, RSR::Dual_placement::AVERAGE);
  CHECK_EQ(num_faces(qem.quads), num_vertices(primal) - qem.stats.joined_triangle_pairs);
  // same orientation as the input: the enclosed volume keeps its sign
  const double v_in = signed_volume(input);
  const double v_dual = signed_volume(qem.quads);
  CHECK(v_in * v_dual > 0);

  const Distance d_qem = distance_to(input, qem.quads), d_average = distance_to(input, average.quads);
  std::cout << name << ": " << num_faces(qem.quads) << " quads, " << qem.stats.joined_triangle_pairs
            << " joined triangle pairs; RMS distance QEM " << d_qem.rms << " vs average "
            << d_average.rms << " (max " << d_qem.max << " vs " << d_average.max << ")" << std::endl;
  CHECK(d_qem.rms < d_average.rms);

  // relaxation: evens out the edges without shrinking
  Mesh relaxed = qem.quads;
  auto planes = relaxed.property_map<Mesh::Vertex_index, RSR::Tangent_planes>("v:planes").first;
  auto dual_normals = relaxed.property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  RSR::relax_on_tangent_planes(relaxed, planes, params::number_of_iterations(3).vertex_normal_map(dual_normals));
  CHECK(CGAL::is_valid_polygon_mesh(relaxed));
  const double volume_before = signed_volume(qem.quads);
  const double volume_after = signed_volume(relaxed);
  const double diagonal_before = bbox_diagonal(qem.quads), diagonal_after = bbox_diagonal(relaxed);
  auto spread = [](const Mesh& m) {
    double sum = 0, sum2 = 0;
    for(auto e : edges(m)) {
      const double l = std::sqrt(CGAL::to_double(CGAL::Polygon_mesh_processing::squared_edge_length(e, m)));
      sum += l;
      sum2 += l * l;
    }
    const double n = double(num_edges(m)), mean = sum / n;
    return std::sqrt(std::max(0., sum2 / n - mean * mean)) / mean;
  };
  const Distance d_relaxed = distance_to(input, relaxed);
  std::cout << "  relaxed: volume " << volume_after / volume_before << " of the dual's, bbox diagonal "
            << diagonal_after / diagonal_before << ", edge-length spread " << spread(qem.quads)
            << " -> " << spread(relaxed) << ", RMS " << d_relaxed.rms << std::endl;
  CHECK(std::abs(volume_after / volume_before - 1) < 0.005);
  CHECK(std::abs(diagonal_after / diagonal_before - 1) < 0.005);
  CHECK(spread(relaxed) < spread(qem.quads));
}

void test_symmetric_eigen()
{
  // A = sum values_k v_k v_k^T must be recovered, vectors orthonormal
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  double worst = 0;
  for(int round = 0; round < 1000; ++round) {
    std::array<std::array<double, 3>, 3> a;
    for(int i = 0; i < 3; ++i)
      for(int j = i; j < 3; ++j)
        a[i][j] = a[j][i] = (round % 3 == 0 && i != j) ? 0. : coordinate(rng);
    if(round % 5 == 0) // rank-deficient: one plane normal only
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j)
          a[i][j] = (i + 1) * (j + 1) * 0.1;
    RSR::internal::Vec3 values;
    std::array<RSR::internal::Vec3, 3> vectors;
    RSR::internal::symmetric_eigen_3(a, values, vectors);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j) {
        double r = 0;
        for(int k = 0; k < 3; ++k)
          r += values[k] * vectors[k][i] * vectors[k][j];
        worst = std::max(worst, std::abs(r - a[i][j]));
        worst = std::max(worst, std::abs(RSR::internal::dot(vectors[i], vectors[j]) - (i == j)));
      }
  }
  std::cout << "symmetric eigen-decomposition: worst residual " << worst << std::endl;
  CHECK(worst < 1e-12);
}

void test_quad_cube()
{
  // the dual of a quad mesh it did not produce: a cube of 3x3 quads per side.
  // Its 8 corners have valence 3 and no valence-3 neighbour: 8 triangles remain.
  Mesh cube = make_lattice_cube(3);
  std::vector<Mesh::Edge_index> diagonals;
  for(auto e : edges(cube)) {
    const auto h = halfedge(e, cube);
    const Vector d = cube.point(target(h, cube)) - cube.point(source(h, cube));
    if(std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z()) > 1.5) // the square's diagonal
      diagonals.push_back(e);
  }
  for(auto e : diagonals)
    CGAL::Euler::join_face(halfedge(e, cube), cube);
  cube.collect_garbage();
  Mesh dual;
  const auto stats = RSR::dualize(cube, dual);
  CHECK(CGAL::is_valid_polygon_mesh(dual));
  CHECK_EQ(euler_characteristic(dual), 2L);
  CHECK_EQ(num_faces(dual), num_vertices(cube));
  CHECK_EQ(stats.non_quads, std::size_t(8));
  CHECK_EQ(stats.quads, num_vertices(cube) - 8);
}

int main(int argc, char** argv)
{
  test_symmetric_eigen();
  test_quad_cube();
  check_input("sphere", make_sphere(1.0, 4), 0.03);
  check_input("torus", make_torus(1.0, 0.4, 120, 60), 0.03);
  check_input("genus 2", make_genus_2(3), 0.02);
  if(argc > 1)
    for(const std::string name : {"elephant", "bunny00", "fandisk"}) {
      Mesh input;
      if(!CGAL::IO::read_polygon_mesh(std::string(argv[1]) + "/" + name + ".off", input)) {
        std::cerr << "cannot read " << name << std::endl;
        ++failures;
        continue;
      }
      check_input(name, input, 0.01);
    }
  return report("test_dual");
}
