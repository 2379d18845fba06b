// progress_gaps MESH.off...
// How often remesh() calls its progress visitor: for each mesh and map (identity,
// position + normal, Gauss map, each at its default-like cell size, with the topology
// check), the run's time, the number of calls and the longest wait between two calls
// (from the start to the first call, between calls, from the last call to the end),
// with the stage it was spent in. A Markdown table on stdout.
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace RSR = CGAL::Range_space_remeshing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Clock = std::chrono::steady_clock;

namespace {

struct Gaps
{
  Clock::time_point last = Clock::now();
  double longest_ms = 0;
  const char* longest_stage = "start";
  double longest_fraction = 0;
  RSR::Remeshing_stage stage = RSR::Remeshing_stage::SCAN;
  double fraction = 0;
  bool started = false;
  std::size_t calls = 0;

  void mark(const char* stage_name)
  {
    const Clock::time_point now = Clock::now();
    const double gap = std::chrono::duration<double, std::milli>(now - last).count();
    if(gap > longest_ms) {
      longest_ms = gap;
      longest_stage = stage_name;
      longest_fraction = fraction;
    }
    last = now;
  }
};

template <class NamedParameters>
void measure(const std::string& name, const char* map, const Mesh& input, const NamedParameters& np)
{
  Gaps gaps;
  const Clock::time_point start = Clock::now();
  Mesh quads;
  try {
    RSR::remesh(input, quads, np.check_topology(true).progress_visitor([&](RSR::Remeshing_stage s, double f) {
      gaps.mark(gaps.started ? RSR::stage_name(gaps.stage) : "before the first call");
      gaps.started = true;
      gaps.stage = s;
      gaps.fraction = f;
      ++gaps.calls;
      return true;
    }));
  } catch(const RSR::Remeshing_error& e) {
    std::printf("| %s | %s | refused: %s | | | |\n", name.c_str(), map, e.what());
    return;
  }
  gaps.mark("after the last call");
  const double total = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::printf("| %s | %s | %zu | %.0f | %zu | %.1f (%s, from %.0f%%) |\n", name.c_str(), map, num_vertices(quads),
              total, gaps.calls, gaps.longest_ms, gaps.longest_stage, 100 * gaps.longest_fraction);
}

} // namespace

int main(int argc, char** argv)
{
  std::printf("| mesh | map | output vertices | run (ms) | calls | longest wait (ms, in the stage of the call before it, from its fraction) |\n");
  std::printf("|---|---|---:|---:|---:|---|\n");
  for(int a = 1; a < argc; ++a) {
    Mesh input;
    if(!CGAL::IO::read_polygon_mesh(argv[a], input) || !CGAL::is_triangle_mesh(input)) {
      std::fprintf(stderr, "cannot read %s\n", argv[a]);
      return 1;
    }
    std::string name = argv[a];
    name = name.substr(name.find_last_of('/') + 1);
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    measure(name, "identity", input, RSR::parameters::grid_spacing(0.01 * diagonal));
    measure(name, "position-normal", input,
            RSR::parameters::range_map(RSR::make_position_normal_range_map(input, 1.0, 0.1 * diagonal))
                .grid_spacing(0.01 * diagonal));
    measure(name, "gauss", input, RSR::parameters::range_map(RSR::make_gauss_range_map(input)).grid_spacing(0.02));
  }
  return 0;
}
