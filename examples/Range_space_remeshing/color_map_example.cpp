// Position + normal + colour in R^9: the grid also bounds the colour's variation per
// face, so faces shrink along colour edges. The input here gets a sharp red/white
// boundary in code; the output's vertices carry colours sampled from the input and
// are written to PLY.
#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <fstream>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double middle = 0.5 * (box.zmin() + box.zmax()), diagonal = bbox_diagonal(input);
  auto colors = input.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(auto v : vertices(input))
    colors[v] = input.point(v).z() > middle ? CGAL::IO::red() : CGAL::IO::white();

  // colour channels in [0, 1] times the colour weight (here 0.3 diagonals): with cells
  // of 0.03 diagonals, a face's colour varies by at most 0.1 per channel
  const auto f = RSR::make_position_normal_color_range_map(input, colors, 1.0, 0.01 * diagonal, 0.3 * diagonal);
  Mesh quads;
  auto out_colors = quads.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  try {
    const auto stats = RSR::remesh(input, quads,
                                   RSR::parameters::range_map(f).grid_spacing(0.03 * diagonal).vertex_color_map(colors),
                                   CGAL::parameters::vertex_color_map(out_colors));
    std::cout << num_faces(input) << " triangles -> " << num_faces(quads) << " coloured quads in "
              << stats.time_total_ms << " ms" << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::ofstream out("colored.ply");
  return CGAL::IO::write_PLY(out, quads, CGAL::parameters::vertex_color_map(out_colors)) ? EXIT_SUCCESS
                                                                                          : EXIT_FAILURE;
}
