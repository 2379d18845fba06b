// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the short examples share: read the input named on the command line (or make
// a sphere), and its bounding-box diagonal, the unit of their cell sizes.
#ifndef RANGE_SPACE_REMESHING_EXAMPLES_EXAMPLE_INPUT_H
#define RANGE_SPACE_REMESHING_EXAMPLES_EXAMPLE_INPUT_H

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <iostream>

/// Reads argv[1] into `mesh`, or makes a subdivided icosahedron when there is no
/// argument; false (with a message) if the file is no triangle mesh.
template <class Mesh>
bool read_example_input(int argc, char** argv, Mesh& mesh)
{
  if(argc < 2) {
    using Point = typename boost::property_traits<
        typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
    CGAL::make_icosahedron(mesh, Point(0, 0, 0), 1.0);
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(3));
    return true;
  }
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || num_faces(mesh) == 0 || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << std::endl;
    return false;
  }
  return true;
}

template <class Mesh>
double bbox_diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

#endif // RANGE_SPACE_REMESHING_EXAMPLES_EXAMPLE_INPUT_H
