// The primal remesh on CGAL's sample meshes (Debian package libcgal-demo):
// invariants, Euler characteristic, components, seeded traversal.
// argv[1]: the folder holding elephant.off, bunny00.off, bones.off, refined_elephant.off.
#include "test_support.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <sstream>

using namespace test;
namespace params = CGAL::parameters;

Mesh load(const std::string& folder, const std::string& name)
{
  Mesh m;
  const bool ok = CGAL::IO::read_polygon_mesh(folder + "/" + name + ".off", m);
  CHECK(ok);
  if(!ok)
    std::cerr << "cannot read " << folder << "/" << name << ".off" << std::endl;
  return m;
}

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: test_cgal_meshes MESH_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string folder = argv[1];

  // Euler characteristic and connectivity kept at well-resolved cell sizes
  for(const std::string name : {"elephant", "bunny00"}) {
    Mesh input = load(folder, name);
    const double diagonal = bbox_diagonal(input);
    for(double relative : {0.02, 0.01}) {
      Mesh out;
      const auto stats = remesh_and_check(input, out, params::grid_spacing(relative * diagonal));
      std::cout << name << " h=" << relative << " diag: " << num_vertices(out) << " vertices, "
                << num_faces(out) << " faces, chi " << euler_characteristic(out) << ", "
                << stats.digons << " digons, " << stats.time_total_ms << " ms" << std::endl;
      CHECK_EQ(euler_characteristic(out), euler_characteristic(input));
      CHECK_EQ(number_of_components(out), number_of_components(input));
      CHECK_EQ(stats.dropped_pieces, std::size_t(0));
    }
  }

  // bones: 26 closed components, all found by the complete scan and by seeding
  {
    Mesh bones = load(folder, "bones");
    CHECK_EQ(number_of_components(bones), std::size_t(26));
    const double h = 0.01 * bbox_diagonal(bones);
    for(auto seeding : {RSR::Seeding_method::COMPLETE_SCAN, RSR::Seeding_method::SEEDED}) {
      Mesh out;
      const auto stats = remesh_and_check(bones, out, params::grid_spacing(h).seeding_method(seeding));
      std::cout << "bones: " << number_of_components(out) << " components, chi "
                << euler_characteristic(out) << std::endl;
      CHECK_EQ(number_of_components(out), std::size_t(26));
      CHECK_EQ(euler_characteristic(out), euler_characteristic(bones));
      CHECK_EQ(stats.mapped_vertices, num_vertices(bones)); // every bone is crossed
    }
  }

  // seeded traversal on a finely tessellated input: only crossed triangles are mapped
  {
    Mesh elephant = load(folder, "refined_elephant");
    const double h = 0.03 * bbox_diagonal(elephant);
    Mesh complete_out, seeded_out;
    const auto complete = remesh_and_check(elephant, complete_out, params::grid_spacing(h));
    const auto seeded = remesh_and_check(
        elephant, seeded_out, params::grid_spacing(h).seeding_method(RSR::Seeding_method::SEEDED));
    std::cout << "refined_elephant: seeded mapped " << seeded.mapped_vertices << " of "
              << num_vertices(elephant) << " vertices (complete: " << complete.mapped_vertices
              << "), visited " << seeded.visited_faces << " of " << num_faces(elephant)
              << " faces" << std::endl;
    CHECK_EQ(complete.mapped_vertices, num_vertices(elephant));
    CHECK(2 * seeded.mapped_vertices < num_vertices(elephant));
    CHECK(fingerprint(seeded_out).size() > 0);
    CHECK_EQ(num_vertices(seeded_out), num_vertices(complete_out));
    CHECK_EQ(euler_characteristic(seeded_out), euler_characteristic(elephant));
  }
  // Coarse cells on thin parts: the primal's parallel edges are split on their arcs, so
  // that its faces, written to OFF and read back by CGAL as a soup, form a polygon
  // mesh (before: bones at 0.05 had 2 parallel edges, read back as edges of four faces)
  std::size_t split = 0;
  for(const std::string name : {"bones", "elephant", "bull"})
    for(double relative : {0.05, 0.07, 0.1}) {
      Mesh input = load(folder, name), out;
      const auto stats = remesh_and_check(input, out, params::grid_spacing(relative * bbox_diagonal(input)));
      split += stats.split_parallel_edges;
      CHECK_EQ(stats.parallel_edges, std::size_t(0));
      std::stringstream file;
      CHECK(CGAL::IO::write_OFF(file, out, params::stream_precision(17)));
      std::vector<Point> points;
      std::vector<std::vector<std::size_t>> polygons;
      CHECK(CGAL::IO::read_OFF(file, points, polygons));
      CHECK_EQ(points.size(), num_vertices(out));
      CHECK_EQ(polygons.size(), num_faces(out));
      CHECK(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons));
    }
  std::cout << "coarse primal remeshes: " << split << " parallel edges split" << std::endl;
  CHECK(split >= 2);
  return report("test_cgal_meshes");
}
