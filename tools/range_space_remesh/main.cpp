// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: command-line front end of the Range_space_remeshing package.
//
//   range_space_remesh [options] INPUT OUTPUT
//
// Reads a mesh (OFF, OBJ, PLY, STL), remeshes it by intersecting its image under
// the range map with a uniform grid, and writes the result (same formats).
// Exit status: 0 on success, 2 on bad arguments or unusable input (one line on
// stderr). The output file is written atomically: it never exists half-written,
// and is not created on failure.
//
// Each header of this directory does one step: options.h the command line,
// map_registry.h and range_maps.h the maps and the remesh, input.h INPUT,
// vertex_cap.h the cap on the output's size, progress.h the progress line and
// Ctrl-C, output.h the files written, topology_report.h and stats.h the reports.

#include "camera_file.h"
#include "failure.h"
#include "input.h"
#include "map_registry.h"
#include "mesh_types.h"
#include "options.h"
#include "output.h"
#include "progress.h"
#include "range_maps.h"
#include "stats.h"
#include "topology_report.h"
#include "vertex_cap.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Range_space_remeshing/version.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/version.h>

#include <gmp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace rsr_program;

/// Answers --help and --version.
int answer_request(const Options& options)
{
  if(options.request == Options::Request::HELP)
    std::cout << usage;
  else
    std::cout << "range_space_remesh " RANGE_SPACE_REMESHING_VERSION_STR " (CGAL " CGAL_VERSION_STR ")\n";
  return EXIT_SUCCESS;
}

/// The cell size in the map's units: --cell-size times the input's bounding-box
/// diagonal (which becomes the length unit of the weights), or times the viewport's
/// diagonal for the view map, unless --absolute. Reads the view map's camera.
double cell_size_in_range_space(const Mesh& input, Options& options)
{
  double h = options.cell_size;
  if(!options.absolute) {
    const CGAL::Bbox_3 box = PMP::bbox(input);
    const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
    double diagonal = std::sqrt(dx * dx + dy * dy + dz * dz);
    if(!(diagonal > 0) || !std::isfinite(diagonal)) // squares out of range (coordinates near 1e300, 1e-300)
      diagonal = std::hypot(std::hypot(dx, dy), dz);
    if(!(diagonal > 0))
      fail("the input's bounding box is a single point");
    if(!std::isfinite(diagonal))
      fail("the input's bounding-box diagonal exceeds the largest double (1.8e308): scale the input down, or give "
           "--absolute --cell-size");
    h *= diagonal;
    if(!std::isfinite(h))
      fail("--cell-size times the bounding-box diagonal exceeds the largest double (1.8e308)");
    options.length_unit = diagonal;
  }
  if(options.map->uses_camera) {
    if(options.camera_file.empty())
      fail("--map " + std::string(options.map->name) + " needs --camera FILE");
    options.camera = read_camera(options.camera_file, options.depth_weight);
    if(!options.absolute) // H: a fraction of the viewport's diagonal
      h = options.cell_size * std::hypot(options.camera.width, options.camera.height);
  }
  return h;
}

/// What the user can change after the library refused: appended to its message.
const char* way_out(RSR::Remeshing_error::Kind kind)
{
  switch(kind) {
  case RSR::Remeshing_error::Kind::OUTPUT_TOO_LARGE:
    return " (use a larger --cell-size, or raise the cap with --max-vertices)";
  case RSR::Remeshing_error::Kind::TARGET_NOT_REACHED:
    return " (ask for another --target-vertices, or raise the cap with --max-vertices)";
  case RSR::Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED:
    return " (leave out --preserve-topology to accept the change, or raise the cap with --max-vertices)";
  default:
    return "";
  }
}

/// Runs the remesh under the progress line; the time limit becomes a Failure, and so
/// does a refinement that cannot finish, with the unit of its cell sizes.
RSR::Remesh_statistics remesh_with_progress(const Mesh& input, double h, Options& options, Mesh& output)
{
  const Input_normals normals(input, options.map->uses_normals && !options.seeded,
                              options.map->uses_normals ? options.normal_smoothing : 0);
  Progress_line progress(options);
  options.progress = &progress;
  RSR::Remesh_statistics stats;
  try {
    stats = remesh(input, normals, h, options, output);
  } catch(const RSR::Remeshing_cancelled& cancelled) {
    progress.clear();
    if(interrupted)
      throw;
    std::ostringstream message;
    message << "the time limit of " << progress.limit() << " s"
            << (options.default_time_limit ? " (--preserve-topology's default)" : "") << " was reached";
    if(cancelled.refinements() > 0)
      message << " after " << cancelled.refinements() << " refinement(s); the finest cell size run to the end, "
              << cancelled.finest_cell_size() * options.cell_size / h // in --cell-size's unit
              << ", still had topology defects";
    else if(options.preserve_topology)
      message << " before the run at the cell size asked ended";
    message << ": nothing was written; give more time with --time-limit S";
    fail(message.str());
  } catch(const RSR::Remeshing_error& error) {
    if(error.kind() != RSR::Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED || options.cell_size == h)
      throw;
    progress.clear();
    std::ostringstream message; // the library's cell sizes are in the map's units
    message << error.what() << way_out(error.kind()) << "; cell sizes in the map's units, in which --cell-size "
            << options.cell_size << " is " << h;
    fail(message.str());
  }
  progress.clear();
  return stats;
}

/// Whether the input's vertex normals all agree (to 1e-9 in each coordinate): the
/// input is flat, and a map of normals alone maps it to a point.
bool has_one_normal(const Mesh& input)
{
  const Input_normals normals(input, true);
  std::array<double, 3> low{{1, 1, 1}}, high{{-1, -1, -1}};
  for(auto v : vertices(input)) {
    const auto n = get(normals, v);
    for(std::size_t q = 0; q < 3; ++q) {
      low[q] = (std::min)(low[q], n[q]);
      high[q] = (std::max)(high[q], n[q]);
    }
  }
  for(std::size_t q = 0; q < 3; ++q)
    if(!(high[q] - low[q] <= 1e-9))
      return false;
  return true;
}

/// The edges of more than two triangles once the faces of `mesh` are split into
/// triangles as the STL writer splits them (the split avoids the edges it can).
std::size_t edges_of_more_than_two_triangles(const Mesh& mesh)
{
  std::vector<Mesh::Point> points;
  std::vector<std::vector<std::size_t>> triangles;
  rsr_io::internal::triangle_soup_of(mesh, points, triangles);
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for(const auto& t : triangles)
    for(std::size_t i = 0; i < 3; ++i)
      edges.push_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::size_t shared = 0;
  for(std::size_t i = 2; i < edges.size(); ++i)
    shared += (edges[i] == edges[i - 2] && (i + 1 == edges.size() || edges[i + 1] != edges[i])) ? 1 : 0;
  return shared;
}

/// Refuses a remesh no mesh file can hold.
void check_remesh(const Mesh& input, const Mesh& output, const RSR::Remesh_statistics& stats, const Options& options)
{
  const bool normals_only = options.map->uses_normals && options.map->dimension == 3;
  if(num_faces(output) == 0 && normals_only && has_one_normal(input))
    fail("the remesh is empty: the input is flat, and --map " + std::string(options.map->name) +
         " maps it to a single point, which no cell size resolves; use a map with positions (identity, "
         "position-normal)");
  if(num_faces(output) == 0)
    fail("the remesh is empty: at this cell size the surface is not resolved (" +
         std::to_string(stats.primal.dropped_pieces + stats.dual.dropped_pieces) +
         " degenerate pieces dropped); use a smaller cell size");
  if(!CGAL::is_valid_polygon_mesh(output))
    fail("internal error: the remesh is not a valid polygon mesh; please report it");
  // Counted on the output itself, whichever stage made them: the primal splits them
  // where it can (Statistics::split_parallel_edges), the dual undoes most of them.
  const std::size_t parallel_edges = RSR::internal::number_of_parallel_edges(output);
  if(parallel_edges > 0)
    fail("at this cell size the " + options.output_kind + " has " + std::to_string(parallel_edges) +
         " pair(s) of parallel edges (parts of the surface thinner than a cell), which a mesh file cannot "
         "store; use a smaller cell size" +
         (options.output_kind == "primal" ? " or the dual output (leave out --output primal)" : " or --output primal"));
  // A vertex where two fans of faces meet (on the border twice) is valid in a halfedge
  // mesh but reads back from a face list as a non-manifold vertex.
  std::vector<Mesh::Halfedge_index> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(output, std::back_inserter(pinched));
  if(!pinched.empty())
    fail("at this cell size the " + options.output_kind + " has " + std::to_string(pinched.size()) +
         " vertex(es) where two fans of faces meet, which a mesh file reads back as non-manifold; use a "
         "smaller cell size");
  if(!rsr_io::format_of(options.output)->stores_polygons) {
    const std::size_t shared = edges_of_more_than_two_triangles(output);
    if(shared > 0)
      fail("the remesh's faces cannot be split into triangles without " + std::to_string(shared) +
           " edge(s) of more than two triangles (faces that share corners beside a part thinner than a cell); "
           "write a format that stores polygons (.off, .obj, .ply) or use a smaller cell size");
  }
}

int run_program(int argc, char** argv)
{
  Options options = parse_arguments(argc, argv);
  if(options.request != Options::Request::REMESH)
    return answer_request(options);
  check_output_names(options);
  check_target_vertices(options, vertex_cap(options)); // before any work
  std::vector<RSR::Topology_defect<Mesh::Face_index>> defects;
  options.defects = &defects;
  Io_times io;
  Input read = read_input(options.input, options.strict, options.sharp_angle);
  io.read_ms = read.read_ms;
  io.repair_ms = read.repair_ms;
  io.uv_seam_vertices = read.uv_seam_vertices;
  io.uv_missing_corners = read.uv_missing_corners;
  io.opened_seam_edges = read.opened_seam_edges;
  io.blended_seam_edges = read.blended_seam_edges;
  io.reader_notes = read.reader_notes;
  const Mesh input = with_creases_opened(std::move(read.mesh), options, read.creases_opened);
  // once, the input read: the runs of --target-vertices and --preserve-topology share it
  const std::size_t cap = vertex_cap(options);
  check_target_vertices(options, cap); // the memory left may have lowered the default cap
  options.max_vertices = cap;

  double h = cell_size_in_range_space(input, options);
  Mesh output;
  const RSR::Remesh_statistics stats = remesh_with_progress(input, h, options, output);
  stop_if_interrupted(); // after the remesh's last report
  if(options.target_vertices > 0) // the size found
    h = stats.primal.cell_size;
  check_remesh(input, output, stats, options);

  const auto write_start = std::chrono::steady_clock::now();
  write_outputs(options, input, output, defects);
  io.write_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - write_start).count();
  report_reader_notes(options.input, read);
  report_repairs(options.input, read.repairs);
  report_dropped_uvs(options.input, read);
  report_unwritten_values(options, input);
  report_blended_seams(options.input, read);
  warn_about_topology(stats, options, defects);
  if(options.stats)
    print_stats(options, input, output, stats, h, read.repairs, io);
  return EXIT_SUCCESS;
}

// GMP cannot report a failed allocation: its manual says the allocation functions
// must not return on failure, and that an exception thrown through GMP is undefined;
// its own functions abort with a message. The program's contract is one line and
// exit 2, with no file left: so does a failed allocation of GMP (and of MPFR, which
// allocates through GMP's functions).
[[noreturn]] void exit_out_of_memory()
{
  rsr_io::internal::remove_pending_files();
  constexpr char line[] = "range_space_remesh: out of memory\n";
  [[maybe_unused]] const auto written = ::write(2, line, sizeof line - 1);
  ::_exit(2);
}

void* gmp_allocate(std::size_t size)
{
  void* p = std::malloc(size);
  if(p == nullptr)
    exit_out_of_memory();
  return p;
}

void* gmp_reallocate(void* old, std::size_t, std::size_t size)
{
  void* p = std::realloc(old, size);
  if(p == nullptr && size > 0)
    exit_out_of_memory();
  return p;
}

void gmp_free(void* p, std::size_t) { std::free(p); }

} // namespace

int main(int argc, char** argv)
{
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
  // CGAL warnings (e.g. a polygon the constrained triangulation cannot handle) are
  // dealt with by the program, and CGAL's failed checks throw with no message of
  // their own: CGAL's default error handler prints several lines on stderr before it
  // throws, where the program's contract is one line per error, which the catch of
  // std::exception below prints.
  CGAL::set_warning_handler([](const char*, const char*, const char*, int, const char*) {});
  CGAL::set_error_handler([](const char*, const char*, const char*, int, const char*) {});
  rsr_io::remove_temporary_files_on_signals();
  std::signal(SIGINT, cancel_on_interrupt);
  try {
    return run_program(argc, argv);
  } catch(const Failure& f) { // escaped: a file name the reader or writer quotes may hold a newline
    std::cerr << "range_space_remesh: " << escaped(f.message) << std::endl;
  } catch(const Interrupted&) {
    std::cerr << interrupted_line << std::flush;
    return interrupted_status;
  } catch(const RSR::Remeshing_error& e) {
    if(e.kind() == RSR::Remeshing_error::Kind::CANCELLED) {
      std::cerr << interrupted_line << std::flush;
      return interrupted_status;
    }
    std::cerr << "range_space_remesh: " << e.what() << way_out(e.kind()) << std::endl;
  } catch(const std::bad_alloc&) {
    std::cerr << "range_space_remesh: out of memory" << std::endl;
  } catch(const std::exception& e) { // one line, whatever the message (CGAL's assertions have several)
    const std::string message = e.what();
    std::cerr << "range_space_remesh: " << message.substr(0, message.find('\n')) << std::endl;
  }
  return 2;
}
