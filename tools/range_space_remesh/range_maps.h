// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the remesh itself. The named parameters every run shares, one
// builder per map of map_registry.h that adds the map to them, and the primal remesh
// or the dual pipeline of --output.

#ifndef RANGE_SPACE_REMESHING_TOOLS_RANGE_MAPS_H
#define RANGE_SPACE_REMESHING_TOOLS_RANGE_MAPS_H

#include "failure.h"
#include "map_registry.h"
#include "mesh_formats.h"
#include "mesh_types.h"
#include "options.h"
#include "progress.h"

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>
#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rsr_program {

/// The output's maps for what `np` gives of the input: its colours and texture
/// coordinates are sampled onto the output.
template <class NamedParameters>
auto output_maps(const NamedParameters&, Mesh& output)
{
  using CGAL::parameters::is_default_parameter;
  constexpr bool colors = !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_color_map_t>::value;
  constexpr bool uvs = !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_texture_map_t>::value;
  auto color_map = [&output] { return output.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first; };
  auto uv_map = [&output] { return output.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first; };
  if constexpr(colors && uvs)
    return RSR::parameters::vertex_color_map(color_map()).vertex_texture_map(uv_map());
  else if constexpr(colors)
    return RSR::parameters::vertex_color_map(color_map());
  else if constexpr(uvs)
    return RSR::parameters::vertex_texture_map(uv_map());
  else
    return CGAL::parameters::default_values();
}

/// The primal remesh, or the whole dual pipeline, with the named parameters `np`
/// (cell size, seeding and, but for the identity, the range map).
template <class NamedParameters>
RSR::Remesh_statistics run(const Mesh& input, const NamedParameters& np, const Options& options, Mesh& output)
{
  const auto np_out = output_maps(np, output);
  RSR::Remesh_statistics stats;
  if(options.output_kind == "primal") {
    stats.primal = RSR::primal_remesh(input, output, np, np_out);
    stats.time_total_ms = stats.primal.time_total_ms;
    return stats;
  }
  const auto placement = options.placement == "average" ? RSR::Dual_placement::AVERAGE
                         : options.placement == "sharp" ? RSR::Dual_placement::SHARP_FEATURES
                                                        : RSR::Dual_placement::QEM;
  const auto np_all =
      np.quad_collapse(options.collapse).dual_placement(placement).number_of_relaxation_steps(options.relax);
  return RSR::remesh(input, output, np_all, np_out);
}

/// `run` with the input's vertex colours and texture coordinates added to `np`, where
/// it has them and OUTPUT's format stores them: sampling the others would be work
/// for nothing, and could refuse an input on which they cannot be sampled.
template <class NamedParameters>
RSR::Remesh_statistics run_with_vertex_values(const Mesh& input, const NamedParameters& np, const Options& options,
                                              Mesh& output)
{
  const auto format = rsr_io::format_of(options.output);
  auto colors = find_vertex_colors(input);
  auto uvs = find_vertex_uvs(input);
  if(!format || !format->stores_colors)
    colors.reset();
  if(!format || !format->stores_uvs)
    uvs.reset();
  if(colors && uvs)
    return run(input, np.vertex_color_map(*colors).vertex_texture_map(*uvs), options, output);
  if(colors)
    return run(input, np.vertex_color_map(*colors), options, output);
  if(uvs)
    return run(input, np.vertex_texture_map(*uvs), options, output);
  return run(input, np, options, output);
}

/// The input's vertex normals for the normal-based maps: from a table computed in one
/// pass over the faces for the complete scan, which maps every vertex (about ten times
/// cheaper than reading each vertex's star on its own), then averaged `smoothing`
/// times over the neighbours (--normal-smoothing); lazily for --seeded, which maps
/// only the vertices the arcs reach, unless they are averaged.
class Input_normals
{
public:
  using key_type = Mesh::Vertex_index;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Input_normals(const Mesh& input, bool all_at_once, int smoothing = 0) : lazy_(input)
  {
    if(!all_at_once && smoothing == 0)
      return;
    table_ = std::make_shared<std::vector<value_type>>(input.num_vertices()); // removed ones included: indices
    const auto table = boost::make_iterator_property_map(table_->begin(), get(boost::vertex_index, input));
    RSR::compute_vertex_normals(input, table);
    if(smoothing > 0)
      RSR::smooth_vertex_normals(input, table, RSR::parameters::number_of_iterations(std::size_t(smoothing)));
  }

  friend value_type get(const Input_normals& map, key_type v)
  {
    return map.table_ ? (*map.table_)[std::size_t(v)] : get(map.lazy_, v);
  }

private:
  RSR::Lazy_vertex_normal_map<Mesh> lazy_;
  std::shared_ptr<std::vector<value_type>> table_; // shared by the maps' copies
};

/// The topology visitor of the program: keeps the defects.
struct Defect_collector
{
  std::vector<RSR::Topology_defect<Mesh::Face_index>>* defects;
  void operator()(const RSR::Topology_defect<Mesh::Face_index>& defect) const { defects->push_back(defect); }
};

/// The named parameters of every run, without the map: cell size `h` (or, with
/// --target-vertices, the one the library finds from it), seeding, cap, topology
/// check, and the progress line, which also stops the run at --time-limit or Ctrl-C.
inline auto shared_parameters(double h, const Options& options)
{
  const auto seeding =
      options.seeded ? RSR::Seeding_method::SEEDED : RSR::Seeding_method::COMPLETE_SCAN;
  Progress_line* progress = options.progress;
  return RSR::parameters::grid_spacing(h)
      .number_of_target_vertices(std::size_t(options.target_vertices)) // 0: none
      .seeding_method(seeding)
      .maximum_number(options.max_vertices)
      .check_topology(options.check_topology && !options.seeded)
      .preserve_topology(options.preserve_topology)
      .refine_around_defects(!options.allow_topology_change)
      .topology_visitor(Defect_collector{options.defects})
      .progress_visitor([progress](RSR::Remeshing_stage stage, double fraction) {
        return (*progress)(stage, fraction);
      });
}

using Shared_parameters = decltype(shared_parameters(0., std::declval<const Options&>()));

struct Map_run
{
  const Mesh& input;
  const Input_normals& normals;
  const Shared_parameters& np;
  const Options& options;
  Mesh& output;
};

// The builders of map_registry.h's table. In relative mode (length_unit = the
// bounding-box diagonal) the weights are scaled so that a cell of size H bounds
// positions by H diagonals and normals by H / W (Gauss map: H, in units of the unit
// cube).

inline RSR::Remesh_statistics remesh_with_identity(const Map_run& r)
{
  return run_with_vertex_values(r.input, r.np, r.options, r.output);
}

inline RSR::Remesh_statistics remesh_with_gauss(const Map_run& r)
{
  return run_with_vertex_values(r.input,
                                r.np.range_map(RSR::Gauss_range_map<Input_normals>(r.normals, r.options.length_unit)),
                                r.options, r.output);
}

inline RSR::Remesh_statistics remesh_with_position_normal(const Map_run& r)
{
  const auto points = get(CGAL::vertex_point, r.input);
  return run_with_vertex_values(r.input,
                                r.np.range_map(RSR::Position_normal_range_map(
                                    points, r.normals, 1.0, r.options.normal_weight * r.options.length_unit)),
                                r.options, r.output);
}

/// --color-weight, or the map's default.
inline double color_weight(const Options& options)
{
  return options.color_weight >= 0 ? options.color_weight : options.map->default_color_weight;
}

inline RSR::Remesh_statistics remesh_with_position_normal_color(const Map_run& r)
{
  const auto points = get(CGAL::vertex_point, r.input);
  const Color_map colors = *find_vertex_colors(r.input); // remesh() checked that there are some
  const double unit = r.options.length_unit, wn = r.options.normal_weight * unit;
  return run_with_vertex_values(r.input,
                                r.np.range_map(RSR::Position_normal_color_range_map(
                                    points, r.normals, colors, 1.0, wn, color_weight(r.options) * unit)),
                                r.options, r.output);
}

inline RSR::Remesh_statistics remesh_with_position_normal_color_gradient(const Map_run& r)
{
  const auto points = get(CGAL::vertex_point, r.input);
  const double unit = r.options.length_unit, wn = r.options.normal_weight * unit;
  const Color_map colors = *find_vertex_colors(r.input); // remesh() checked that there are some
  // gradient magnitudes are colour per length: one more length unit
  const RSR::Color_gradient_magnitude_map<Mesh, Color_map> gradients(r.input, colors);
  return run_with_vertex_values(r.input,
                                r.np.range_map(RSR::Position_normal_color_range_map(
                                    points, r.normals, gradients, 1.0, wn, color_weight(r.options) * unit * unit)),
                                r.options, r.output);
}

inline RSR::Remesh_statistics remesh_with_view(const Map_run& r)
{
  using View_map = RSR::View_range_map<boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>;
  return run_with_vertex_values(
      r.input, r.np.range_map(View_map(get(CGAL::vertex_point, r.input), r.options.camera, r.options.depth_weight)),
      r.options, r.output);
}

/// Remeshes with the map of the options, at cell size `h` or, with --target-vertices,
/// at the one the library finds from it.
inline RSR::Remesh_statistics remesh(const Mesh& input, const Input_normals& normals, double h,
                                     const Options& options, Mesh& output)
{
  if(options.seeded && options.preserve_topology)
    fail("--preserve-topology needs the complete scan: drop --seeded");
  options.defects->clear();
  if(options.map->uses_colors && !find_vertex_colors(input))
    fail("--map " + std::string(options.map->name) + " needs vertex colours: give a PLY, COFF or OBJ input with colours");
  const Shared_parameters np = shared_parameters(h, options);
  return options.map->remesh(Map_run{input, normals, np, options, output});
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_RANGE_MAPS_H
