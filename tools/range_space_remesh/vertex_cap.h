// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the cap on the output's size (--max-vertices, or what the
// available memory holds), checked before any work and again once the input is read.

#ifndef RANGE_SPACE_REMESHING_TOOLS_VERTEX_CAP_H
#define RANGE_SPACE_REMESHING_TOOLS_VERTEX_CAP_H

#include "failure.h"
#include "options.h"

#include <CGAL/Range_space_remeshing/remesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>

namespace rsr_program {

/// The first number in the file (0 if none: "max", a missing file).
inline double number_in_file(const char* path)
{
  std::ifstream in(path);
  double x = 0;
  return in >> x ? x : 0;
}

/// The kilobytes of the line `key` ("VmSize:") of /proc/self/status, 0 if none.
inline double own_status_kilobytes(const std::string& key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, key.size(), key) == 0)
      return std::atof(line.c_str() + key.size());
  return 0;
}

/// The bytes this process may still map under its limits on address space (`ulimit -v`)
/// and data (`ulimit -d`), 0 if it has none: past them an allocation fails however much
/// memory the machine has.
inline double address_space_left()
{
  double left = 0;
  const std::pair<int, const char*> limits[] = {{RLIMIT_AS, "VmSize:"}, {RLIMIT_DATA, "VmData:"}};
  for(const auto& [resource, key] : limits) {
    rlimit limit{};
    if(::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
      continue;
    const double room = (std::max)(double(limit.rlim_cur) - 1024 * own_status_kilobytes(key), 1.0);
    if(left == 0 || room < left)
      left = room;
  }
  return left;
}

/// The memory this process can still take, in bytes: Linux' MemAvailable, or less
/// inside a container whose memory limit (cgroup v2, else v1) is lower or under a
/// process limit (`ulimit -v`, `-d`); 0 if unknown.
inline double available_memory()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kilobytes = 0, available = 0;
  while(meminfo >> key >> kilobytes >> unit)
    if(key == "MemAvailable:") {
      available = kilobytes * 1024;
      break;
    }
  const std::pair<const char*, const char*> limits[] = {
      {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
      {"/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes"}};
  for(const auto& [limit_file, usage_file] : limits) {
    const double limit = number_in_file(limit_file); // no limit: "max" (0 here) or about 2^63
    if(limit > 0 && limit < 1e18) {
      const double left = (std::max)(limit - number_in_file(usage_file), 1.0);
      if(available == 0 || left < available)
        available = left;
    }
  }
  const double process_left = address_space_left();
  if(process_left > 0 && (available == 0 || process_left < available))
    available = process_left;
  return available;
}

/// The cap on the primal remesh's vertices: --max-vertices, or the library's default
/// lowered so that the run fits in three quarters of the available memory. A cell size
/// far too small is then refused at once with a message, where it would otherwise run
/// for minutes and end killed for want of memory. Bytes per primal vertex as measured
/// on refined_elephant with 3.9 million of them (peak resident size, input included).
inline std::size_t vertex_cap(const Options& options)
{
  if(options.max_vertices > 0)
    return options.max_vertices;
  const double bytes_per_vertex = options.output_kind == "primal" ? 400 : 1300;
  const double fitting = 0.75 * available_memory() / bytes_per_vertex;
  std::size_t cap = RSR::default_maximum_number_of_vertices;
  if(fitting > 0 && fitting < double(cap))
    cap = (std::max)(std::size_t(fitting), std::size_t(100000));
  return cap;
}

/// Refuses a --target-vertices above the cap `cap`, which no cell size could give
/// without exceeding it: the search would only run in vain.
inline void check_target_vertices(const Options& options, std::size_t cap)
{
  if(options.target_vertices > 0 && std::size_t(options.target_vertices) > cap)
    fail("--target-vertices " + std::to_string(options.target_vertices) + " is above the cap of " +
         std::to_string(cap) + " output vertices (" +
         (options.max_vertices > 0 ? "--max-vertices" : "the default for the available memory") +
         "): ask for fewer, or raise the cap with --max-vertices");
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_VERTEX_CAP_H
