// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the range maps of --map, in one table. What the program does
// differently for one map (its dimension in --stats, whether it reads the input's
// normals, --normal-weight, vertex colours or --camera, and how the remesh is run
// with it) is read from its row here, so that a new map is one more row and one more
// builder in range_maps.h.

#ifndef RANGE_SPACE_REMESHING_TOOLS_MAP_REGISTRY_H
#define RANGE_SPACE_REMESHING_TOOLS_MAP_REGISTRY_H

#include "mesh_types.h"

#include <CGAL/Range_space_remeshing/remesh.h>

#include <array>
#include <string>

namespace rsr_program {

/// The input, the named parameters and the options of one remesh (range_maps.h).
struct Map_run;

/// One map of --map.
struct Range_map
{
  const char* name;
  int dimension;                 // D, the range space's
  bool uses_normals;             // maps the input's vertex normals
  bool uses_normal_weight;       // scales the normal by --normal-weight
  bool uses_colors;              // maps vertex colours, scaled by --color-weight
  double default_color_weight;   // without --color-weight
  bool uses_camera;              // needs --camera
  RSR::Remesh_statistics (*remesh)(const Map_run&); // runs the remesh with this map
};

// the builders of the maps (range_maps.h)
inline RSR::Remesh_statistics remesh_with_identity(const Map_run& run);
inline RSR::Remesh_statistics remesh_with_gauss(const Map_run& run);
inline RSR::Remesh_statistics remesh_with_position_normal(const Map_run& run);
inline RSR::Remesh_statistics remesh_with_position_normal_color(const Map_run& run);
inline RSR::Remesh_statistics remesh_with_position_normal_color_gradient(const Map_run& run);
inline RSR::Remesh_statistics remesh_with_view(const Map_run& run);

/// The maps, in the order --help and the unknown-map message list them; the first is
/// the default. Gradients of sharp colour edges reach 1 / (edge length): the gradient
/// map's default colour weight is smaller.
inline const std::array<Range_map, 6>& range_maps()
{
  static const std::array<Range_map, 6> table = {{
      // name                            D  normals n.weight colors default camera builder
      {"identity",                       3, false,  false,   false, 0.,     false, remesh_with_identity},
      {"gauss",                          3, true,   false,   false, 0.,     false, remesh_with_gauss},
      {"position-normal",                6, true,   true,    false, 0.,     false, remesh_with_position_normal},
      {"position-normal-color",          9, true,   true,    true,  1.,     false, remesh_with_position_normal_color},
      {"position-normal-color-gradient", 9, true,   true,    true,  0.01,   false,
       remesh_with_position_normal_color_gradient},
      {"view",                           3, false,  false,   false, 0.,     true,  remesh_with_view},
  }};
  return table;
}

/// The map named `name`, or null.
inline const Range_map* find_range_map(const std::string& name)
{
  for(const Range_map& map : range_maps())
    if(name == map.name)
      return &map;
  return nullptr;
}

/// The default map (the identity).
inline const Range_map& default_range_map() { return range_maps().front(); }

/// "identity, gauss, ...": the names, for a message.
inline std::string range_map_names()
{
  std::string names;
  for(const Range_map& map : range_maps())
    names += (names.empty() ? "" : ", ") + std::string(map.name);
  return names;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_MAP_REGISTRY_H
