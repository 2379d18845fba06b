// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the camera file of --map view (see --help).

#ifndef RANGE_SPACE_REMESHING_TOOLS_CAMERA_FILE_H
#define RANGE_SPACE_REMESHING_TOOLS_CAMERA_FILE_H

#include "failure.h"
#include "mesh_types.h"

#include <CGAL/Range_space_remeshing/View_range_map.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace rsr_program {

/// Reads a camera file (see --help); sets the depth weight to the pixels per unit
/// of a lateral step at the target's distance.
inline RSR::Camera read_camera(const std::string& path, double& depth_weight)
{
  // a few lines of text: refuse what is not a small regular file (/dev/zero would
  // be one endless line)
  std::error_code error;
  if(!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) > 65536 || error)
    fail("cannot read the camera file " + quote(path) + " (not a regular file of at most 64 KB)");
  std::ifstream in(path);
  if(!in)
    fail("cannot read the camera file " + quote(path));
  std::array<double, 3> eye{}, target{}, up = {{0, 1, 0}};
  double fov = 60, width = 0, height = 0;
  bool has_eye = false, has_target = false;
  std::string line;
  for(int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string key;
    if(!(words >> key))
      continue;
    auto numbers = [&](int count) {
      std::vector<double> values(count);
      for(double& x : values)
        if(!(words >> x) || !std::isfinite(x))
          fail("camera file " + quote(path) + ", line " + std::to_string(number) + ": " + quote(key) + " expects " +
               std::to_string(count) + " finite number(s)");
      std::string extra;
      if(words >> extra)
        fail("camera file " + quote(path) + ", line " + std::to_string(number) + ": unexpected " + quote(extra));
      return values;
    };
    if(key == "eye" || key == "target" || key == "up") {
      const auto v = numbers(3);
      (key == "eye" ? eye : key == "target" ? target : up) = {{v[0], v[1], v[2]}};
      has_eye = has_eye || key == "eye";
      has_target = has_target || key == "target";
    } else if(key == "fov") {
      fov = numbers(1)[0];
    } else if(key == "viewport") {
      const auto v = numbers(2);
      width = v[0];
      height = v[1];
    } else {
      fail("camera file " + quote(path) + ", line " + std::to_string(number) + ": unknown keyword " + quote(key));
    }
  }
  if(!has_eye || !has_target || !(width > 0))
    fail("camera file " + quote(path) + " needs eye, target and viewport lines");
  try {
    const RSR::Camera camera = RSR::make_look_at_camera(eye, target, up, fov, width, height);
    const double distance = std::sqrt(CGAL::square(eye[0] - target[0]) + CGAL::square(eye[1] - target[1]) +
                                      CGAL::square(eye[2] - target[2]));
    depth_weight = height / 2 / std::tan(fov * M_PI / 360) / distance;
    return camera;
  } catch(const RSR::Remeshing_error& e) {
    fail("camera file " + quote(path) + ": " + e.what());
  }
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_CAMERA_FILE_H
