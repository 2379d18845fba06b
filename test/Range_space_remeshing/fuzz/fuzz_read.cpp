// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the command-line program's reader on any bytes, prepare_input() on
// what it reads, and its writers on what that gives, each output read back: text
// formats and binary PLY must give back the same vertices and faces. Fast (no
// remeshing), so it reaches deep into the formats. Anything but a clean Read_error or
// Remeshing_error, a crash, a sanitizer report or a broken invariant, aborts.
//
// Input layout: 1 header byte (format: OFF, OBJ, PLY, STL), then the file's bytes.
//
// Built with -fsanitize=fuzzer by scripts/fuzz.sh; built without, `main` below
// replays files (its seed corpus and regressions) as a ctest.

#include "mesh_file_reader.h"
#include "replay_files.h"
#include "mesh_file_writer.h"

#include <CGAL/Range_space_remeshing/prepare_input.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Color_map = Mesh::Property_map<Mesh::Vertex_index, CGAL::IO::Color>;
namespace RSR = CGAL::Range_space_remeshing;

const char* const extensions[] = {"off", "obj", "ply", "stl"};

[[noreturn]] void broken(const std::string& what)
{
  std::cerr << "fuzz_read: invariant broken: " << what << std::endl;
  std::abort();
}

/// The triangle mesh of a soup, or false if prepare_input() refuses it.
bool mesh_of(const rsr_io::Polygon_soup& soup, Mesh& mesh)
{
  std::vector<K::Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  auto polygons = soup.polygons;
  try {
    RSR::prepare_input(points, polygons, mesh);
  } catch(const RSR::Remeshing_error&) {
    return false;
  }
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    broken("prepare_input() gave no valid triangle mesh");
  return true;
}

void run_one(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  rsr_io::Polygon_soup soup;
  try {
    soup = rsr_io::internal::parse_mesh(text, extensions[data[0] % 4], "the input");
  } catch(const rsr_io::Read_error&) {
    return;
  }
  if(!soup.colors.empty() && soup.colors.size() != soup.points.size())
    broken("colours not one per point");
  if(soup.points.size() > 20000 || soup.polygons.size() > 20000)
    return;
  Mesh mesh;
  if(!mesh_of(soup, mesh))
    return;
  // a soup the repair leaves as it is, the reader must read back as it was written
  for(const std::string ext : {"off", "obj", "ply", "stl"})
    for(const bool binary : {false, true}) {
      std::ostringstream out;
      if(!rsr_io::write_mesh(out, mesh, ext, static_cast<const Color_map*>(nullptr), rsr_io::Write_options{binary, 17}))
        broken("cannot write " + ext);
      rsr_io::Polygon_soup back;
      try {
        back = rsr_io::internal::parse_mesh(out.str(), ext, "the output");
      } catch(const rsr_io::Read_error& e) {
        broken("cannot read back the " + ext + " it wrote: " + e.what());
      }
      if(ext == "stl") // floats, every triangle on its own: counts only
        continue;
      if(back.points.size() != num_vertices(mesh) || back.polygons.size() != num_faces(mesh))
        broken(ext + " read back with other counts");
      std::size_t i = 0;
      for(auto v : vertices(mesh)) {
        const auto& p = mesh.point(v);
        const auto& q = back.points[i++];
        if(!(p.x() == q[0] && p.y() == q[1] && p.z() == q[2]))
          broken(ext + " read back with another point");
      }
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
  return replay_files(argc, argv, "fuzz_read", run_one);
}
#endif
