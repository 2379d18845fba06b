// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: --stats, one JSON object on stdout with the run's counts and
// times (nlohmann's JSON library).

#ifndef RANGE_SPACE_REMESHING_TOOLS_STATS_H
#define RANGE_SPACE_REMESHING_TOOLS_STATS_H

#include "mesh_formats.h"
#include "mesh_types.h"
#include "options.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Range_space_remeshing/prepare_input.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace rsr_program {

inline std::size_t components(const Mesh& mesh)
{
  std::vector<std::size_t> ids(num_faces(mesh));
  return PMP::connected_components(
      mesh, CGAL::make_property_map(ids));
}

inline std::size_t border_cycles(const Mesh& mesh)
{
  std::vector<bool> seen(mesh.number_of_halfedges(), false);
  std::size_t cycles = 0;
  for(auto h : halfedges(mesh)) {
    if(!is_border(h, mesh) || seen[h.idx()])
      continue;
    ++cycles;
    for(auto g : CGAL::halfedges_around_face(h, mesh))
      seen[g.idx()] = true;
  }
  return cycles;
}


/// Where the run's time went outside the remesher.
struct Io_times
{
  double read_ms = 0, repair_ms = 0, write_ms = 0;
  // what the reading dropped the UVs for: a texture seam, corners without UVs
  std::size_t uv_seam_vertices = 0, uv_missing_corners = 0;
  // edges where the file's colours or UVs change: opened (closed surface) or blended
  std::size_t opened_seam_edges = 0, blended_seam_edges = 0;
  std::vector<std::string> reader_notes; // where the file was taken otherwise than it says
};

inline void print_stats(const Options& options, const Mesh& input, const Mesh& output, const RSR::Remesh_statistics& all,
                 double h, const RSR::Input_repair_statistics& repairs, const Io_times& io)
{
  using nlohmann::json;
  const RSR::Statistics& s = all.primal;
  std::map<std::size_t, std::size_t> valences;
  for(auto v : vertices(output))
    ++valences[degree(v, output)];
  std::size_t quads = 0;
  for(auto f : faces(output))
    quads += (degree(f, output) == 4);
  // file names may hold any byte: replace what is not UTF-8 rather than fail
  const auto error_handler = json::error_handler_t::replace;
  json j;
  j["input"] = options.input;
  j["output"] = options.output;
  j["map"] = options.map->name;
  j["D"] = options.map->dimension;
  j["normal_weight"] = options.map->uses_normal_weight ? options.normal_weight : 0.;
  j["normal_smoothing"] = options.map->uses_normals ? options.normal_smoothing : 0;
  j["cell_size"] = h;
  j["seeding"] = options.seeded ? "seeded" : "complete";
  j["output_kind"] = options.output_kind;
  j["placement"] = options.placement;
  j["collapse"] = options.collapse;
  j["relaxation_steps"] = options.relax;
  j["time_limit"] = options.time_limit; // 0: none
  j["triangulated"] = repairs.triangulated_polygons > 0;
  j["input_vertices"] = num_vertices(input);
  j["input_faces"] = num_faces(input);
  j["input_components"] = components(input);
  j["output_vertices"] = num_vertices(output);
  j["output_edges"] = num_edges(output);
  j["output_faces"] = num_faces(output);
  j["output_components"] = components(output);
  j["mapped_vertices"] = s.mapped_vertices;
  j["visited_faces"] = s.visited_faces;
  j["intersection_vertices"] = s.intersection_vertices;
  j["digons"] = s.digons;
  j["non_simple_faces"] = s.non_simple_faces;
  j["dropped_pieces"] = s.dropped_pieces;
  j["split_parallel_edges"] = s.split_parallel_edges;
  j["input_border_cycles"] = border_cycles(input);
  j["output_border_cycles"] = border_cycles(output);
  j["boundary_digons"] = s.boundary_digons;
  j["boundary_corners"] = s.boundary_corners;
  j["uncrossed_border_cycles"] = s.uncrossed_border_cycles;
  j["quads"] = quads;
  j["non_quads"] = num_faces(output) - quads;
  j["joined_triangle_pairs"] = all.dual.joined_triangle_pairs;
  j["dual_dropped_pieces"] = all.dual.dropped_pieces;
  j["removed_pinches"] = all.dual.removed_pinches;
  j["joined_parallel_edges"] = all.dual.joined_parallel_edges;
  j["all_quads"] = {{"non_quads_before", all.all_quads.non_quads_before},
                    {"split_faces", all.all_quads.split_faces},
                    {"triangle_steps", all.all_quads.triangle_steps},
                    {"joined_triangles", all.all_quads.joined_triangles},
                    {"non_quads_after", all.all_quads.non_quads_after},
                    {"pieces_not_all_quads", all.all_quads.pieces_not_all_quads}};
  j["collapsed_quads"] = all.collapse.collapsed_quads;
  j["removed_doublets"] = all.collapse.removed_doublets;
  j["rotated_edges"] = all.collapse.rotated_edges;
  j["neutral_rotations"] = all.collapse.neutral_rotations;
  j["untangle"] = {{"folded_before", all.untangle.folded_before},
                   {"non_convex_before", all.untangle.non_convex_before},
                   {"folded_after", all.untangle.folded_after},
                   {"non_convex_after", all.untangle.non_convex_after},
                   {"moves", all.untangle.moves},
                   {"rounds", all.untangle.rounds},
                   {"tries", all.untangle.tries},
                   {"vertices_before", all.untangle.vertices_before},
                   {"collapses", all.untangle.collapses},
                   {"rotations", all.untangle.rotations},
                   {"moves_off_surface", all.untangle.moves_off_surface}};
  j["cell_size_used"] = s.cell_size;
  const bool carried = find_vertex_uvs(output).has_value();
  j["texture_coordinates"] = {{"carried", carried},
                              {"written", carried && rsr_io::format_of(options.output)->stores_uvs},
                              {"seam_vertices", io.uv_seam_vertices},
                              {"corners_without", io.uv_missing_corners}};
  j["vertex_colors"] = {{"read", find_vertex_colors(input).has_value()},
                        {"written", find_vertex_colors(output).has_value() &&
                                        rsr_io::format_of(options.output)->stores_colors}};
  j["input_notes"] = io.reader_notes;
  j["attribute_seams"] = {{"opened_edges", io.opened_seam_edges}, {"blended_edges", io.blended_seam_edges}};
  j["input_repairs"] = {{"repaired", repairs.repaired()},
                        {"merged_points", repairs.merged_points},
                        {"removed_isolated_points", repairs.removed_isolated_points},
                        {"removed_repeated_corners", repairs.removed_repeated_corners},
                        {"removed_degenerate_faces", repairs.removed_degenerate_polygons},
                        {"removed_duplicate_faces", repairs.removed_duplicate_polygons},
                        {"flipped_faces", repairs.reversed_polygons},
                        {"flipped_to_face_outward", repairs.reversed_to_face_outward},
                        {"non_manifold_edges", repairs.non_manifold_edges},
                        {"split_non_manifold_points", repairs.split_non_manifold_points},
                        {"triangulated_faces", repairs.triangulated_polygons}};
  j["topology"] = {{"checked", s.topology_checked},
                   {"preserved", options.output_kind == "primal" ? s.topology_preserved() : all.topology_preserved()},
                   {"closed_loops", s.closed_loops},
                   {"harmless_loops", s.harmless_loops},
                   {"non_disk_cells", s.non_disk_cells},
                   {"lost_components", s.lost_components},
                   {"input_euler_characteristic", s.input_euler_characteristic},
                   {"primal_euler_characteristic", s.output_euler_characteristic},
                   {"refinements", s.topology_refinements},
                   {"local_refinements", s.local_refinements},
                   {"magnified_regions", s.magnified_regions},
                   {"largest_magnification", s.largest_magnification}};
  json histogram = json::object();
  for(const auto& [valence, count] : valences)
    histogram[std::to_string(valence)] = count;
  j["valence_histogram"] = histogram;
  j["time_ms"] = {{"read", io.read_ms},         {"repair", io.repair_ms},
                  {"seeding", s.time_seeding_ms}, {"tracing", s.time_tracing_ms},
                  {"faces", s.time_faces_ms},     {"topology", s.time_topology_ms},
                  {"output", s.time_output_ms},   {"dual", all.dual.time_ms},
                  {"all_quads", all.all_quads.time_ms}, {"collapse", all.collapse.time_ms},
                  {"relaxation", all.time_relaxation_ms},
                  {"untangle", all.untangle.time_ms}, {"attributes", all.time_attributes_ms},
                  {"total", all.time_total_ms},   {"write", io.write_ms}};
  std::cout << j.dump(-1, ' ', false, error_handler) << std::endl;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_STATS_H
