// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the command-line program's input path (its OFF, OBJ, PLY and STL
// reader, then prepare_input()'s check and repair) and the remesher on what it accepts, with a map
// and a cell size taken from the input. Bad input must end in a clean exception;
// anything else (a crash, a sanitizer report, a broken invariant) aborts.
//
// Input layout: 6 header bytes, then the file's text.
//   [0] format: OFF, OBJ, PLY, STL         [1] map: identity, Gauss, R^6, R^5 user map
//   [2] flags: bit 0 seeded, bits 1-2 relaxation steps, bit 3 no collapse,
//       bit 4 grid origin at half a cell
//   [3..4] cell size: 0..7 absurd values (0, -1, NaN, inf, 1e-300, 1e300, denormal,
//       1e-9), otherwise a fraction of the bounding-box diagonal in [0.03, 3]
//   [5] normal weight of the R^6 map, in [0, 4]
//
// Built with -fsanitize=fuzzer by scripts/fuzz.sh; built without, `main` below
// replays files (the seed corpus and the regressions) as a ctest.

#include "../test_support.h"
#include "mesh_file_reader.h"
#include "replay_files.h"

#include <CGAL/Range_space_remeshing/prepare_input.h>

#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace test;

/// (x, y, z, x, 0.5): a duplicated and a constant coordinate, both degenerate for
/// the grid (every vertex lies on the same hyperplane of the last axis when the
/// cell size divides 0.5).
struct Duplicated_and_constant_map
{
  using key_type = Mesh::Vertex_index;
  using value_type = std::array<double, 5>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const Mesh* mesh;
  friend value_type get(const Duplicated_and_constant_map& f, key_type v)
  {
    const Point& p = f.mesh->point(v);
    return {{p.x(), p.y(), p.z(), p.x(), 0.5}};
  }
};

double cell_size_from(std::uint16_t code, double diagonal)
{
  switch(code) {
  case 0: return 0.;
  case 1: return -1.;
  case 2: return std::numeric_limits<double>::quiet_NaN();
  case 3: return std::numeric_limits<double>::infinity();
  case 4: return 1e-300;
  case 5: return 1e300;
  case 6: return std::numeric_limits<double>::denorm_min();
  case 7: return 1e-9;
  default: break;
  }
  const double fraction = 0.03 * std::pow(100., double(code) / 65535.);
  return diagonal > 0 ? fraction * diagonal : fraction;
}

/// The program's reader (mesh_file_reader.h) on `text` as a file of the format
/// `format` (0 OFF, 1 OBJ, 2 PLY, 3 STL); false if it refuses the text.
bool read_soup(int format, const std::string& text, std::vector<Point>& points,
               std::vector<std::vector<std::size_t>>& polygons)
{
  static const char* const extensions[] = {"off", "obj", "ply", "stl"};
  try {
    rsr_io::Polygon_soup soup = rsr_io::internal::parse_mesh(text, extensions[format], "the input");
    for(const auto& p : soup.points)
      points.emplace_back(p[0], p[1], p[2]);
    polygons = std::move(soup.polygons);
    return true;
  } catch(const rsr_io::Read_error&) {
    return false;
  }
}

[[noreturn]] void broken(const char* what)
{
  std::cerr << "fuzz_remesh: invariant broken: " << what << std::endl;
  std::abort();
}

/// The primal with every invariant of test_support.h, then the whole pipeline.
template <class NP>
void remesh_and_verify(const Mesh& mesh, const NP& np)
{
  Mesh primal;
  const int failures_before = failures;
  remesh_and_check(mesh, primal, np);
  if(failures != failures_before)
    broken("primal remesh (see the CHECK lines above)");
  Mesh quads;
  RSR::remesh(mesh, quads, np);
  if(!CGAL::is_valid_polygon_mesh(quads))
    broken("the dual pipeline's output is not a valid polygon mesh");
}

void run_one(const std::uint8_t* data, std::size_t size)
{
  if(size < 6)
    return;
  const int format = data[0] % 4, map = data[1] % 4, flags = data[2];
  const std::uint16_t cell_code = std::uint16_t(data[3] | (data[4] << 8));
  const double normal_weight = 4. * data[5] / 255.;
  const std::string text(reinterpret_cast<const char*>(data + 6), size - 6);

  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!read_soup(format, text, points, polygons) || points.size() > 5000 || polygons.size() > 5000)
    return;
  Mesh mesh;
  try {
    RSR::prepare_input(points, polygons, mesh);
  } catch(const RSR::Remeshing_error&) {
    return;
  }
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    broken("prepare_input() gave no valid triangle mesh");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double h = cell_size_from(cell_code, diagonal);
  const double shift = (flags & 16) ? 0.5 * h : 0.;
  const auto np = RSR::parameters::grid_spacing(h)
                      .seeding_method((flags & 1) ? RSR::Seeding_method::SEEDED : RSR::Seeding_method::COMPLETE_SCAN)
                      .number_of_relaxation_steps((flags >> 1) & 3)
                      .maximum_number(std::size_t(200000));
  const auto collapse = np.quad_collapse(!(flags & 8));
  try {
    if(map == 0)
      remesh_and_verify(mesh, collapse.grid_origin(RSR::Range_space_traits<3>::Point_d{{shift, shift, shift}}));
    else if(map == 1)
      remesh_and_verify(mesh, collapse.range_map(RSR::make_gauss_range_map(mesh)));
    else if(map == 2)
      remesh_and_verify(mesh, collapse.range_map(RSR::make_position_normal_range_map(mesh, 1., normal_weight)));
    else
      remesh_and_verify(mesh, collapse.range_map(Duplicated_and_constant_map{&mesh}));
  } catch(const RSR::Remeshing_error&) {
    // bad input, reported cleanly: what the library promises
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  run_one(data, size);
  return 0;
}

#ifndef RSR_LIBFUZZER
int main(int argc, char** argv)
{
  if(const int status = replay_files(argc, argv, "fuzz_remesh", run_one))
    return status;
  return report("fuzz_remesh");
}
#endif
