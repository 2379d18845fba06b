// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the mesh type the program reads into and writes from, and its
// vertex colours.

#ifndef RANGE_SPACE_REMESHING_TOOLS_MESH_TYPES_H
#define RANGE_SPACE_REMESHING_TOOLS_MESH_TYPES_H

#include <CGAL/Range_space_remeshing/remesh.h> // declares the namespaces aliased below

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

#include <optional>
#include <string>

namespace rsr_program {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Color_map = Mesh::Property_map<Mesh::Vertex_index, CGAL::IO::Color>;
using UV_map = Mesh::Property_map<Mesh::Vertex_index, K::Point_2>;
namespace RSR = CGAL::Range_space_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The mesh's vertex property `name` of values `T`, if it has it.
template <class T>
std::optional<Mesh::Property_map<Mesh::Vertex_index, T>> find_vertex_property(const Mesh& mesh, const std::string& name)
{
#if CGAL_VERSION_NR >= 1060000000 // Surface_mesh::property_map() returns an optional since CGAL 6
  return mesh.property_map<Mesh::Vertex_index, T>(name);
#else
  const auto [map, found] = mesh.property_map<Mesh::Vertex_index, T>(name);
  return found ? std::optional<Mesh::Property_map<Mesh::Vertex_index, T>>(map) : std::nullopt;
#endif
}

/// The mesh's vertex colours ("v:color"), if it has them.
inline std::optional<Color_map> find_vertex_colors(const Mesh& mesh)
{
  return find_vertex_property<CGAL::IO::Color>(mesh, "v:color");
}

/// The mesh's texture coordinates ("v:uv"), if it has them.
inline std::optional<UV_map> find_vertex_uvs(const Mesh& mesh) { return find_vertex_property<K::Point_2>(mesh, "v:uv"); }

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_MESH_TYPES_H
