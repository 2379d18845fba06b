// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the command-line program's option parser (options.h) on any command
// line. It must accept the line or refuse it with the program's Failure, whose
// message is one line (main() prints it as the one line on stderr); what it accepts
// must keep every option in its documented domain. Anything else (a crash, another
// exception, a sanitizer report, a broken invariant) aborts.
//
// Input layout: the arguments argv[1..], separated by NUL bytes (argv[0] is the
// program's name).
//
// Built with -fsanitize=fuzzer by scripts/fuzz.sh; built without, `main` below
// replays files (its seed corpus and regressions) as a ctest.

#include "options.h"
#include "range_maps.h" // the builders map_registry.h's table points to
#include "replay_files.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace rsr_program;

[[noreturn]] void broken(const std::string& what)
{
  std::cerr << "fuzz_options: invariant broken: " << what << std::endl;
  std::abort();
}

/// The arguments of `data`, split at its NUL bytes.
std::vector<std::string> arguments_of(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> arguments{"range_space_remesh"};
  std::string current;
  for(std::size_t i = 0; i < size; ++i) {
    if(data[i] == 0) {
      arguments.push_back(current);
      current.clear();
    } else {
      current += char(data[i]);
    }
  }
  if(size > 0)
    arguments.push_back(current);
  return arguments;
}

/// A refusal is one line of printable text: no control character.
void check_refusal(const Failure& failure)
{
  if(failure.message.empty())
    broken("an empty message");
  for(const unsigned char c : failure.message)
    if(c < 0x20 || c == 0x7f)
      broken("a control character in the message: " + quote(failure.message));
}

bool in(double x, double low, double high) { return x >= low && x <= high; }

/// What the parser accepted is within the domains the usage text gives.
void check_accepted(const Options& o, int argc)
{
  if(o.request != Options::Request::REMESH) {
    if(argc != 2)
      broken("--help or --version with other arguments");
    return;
  }
  if(o.map == nullptr || find_range_map(o.map->name) != o.map)
    broken("a map that is not in the table");
  if(!(o.cell_size > 0) || !std::isfinite(o.cell_size))
    broken("cell size " + std::to_string(o.cell_size));
  if(!in(o.normal_weight, 0, 1e6) || !(o.color_weight == -1 || in(o.color_weight, 0, 1e6)))
    broken("a weight out of its domain");
  if(!(o.sharp_angle == -1 || in(o.sharp_angle, 0, 180)))
    broken("sharp angle " + std::to_string(o.sharp_angle));
  if(!in(o.relax, 0, 1000) || !(o.time_limit == 0 || (o.time_limit > 0 && o.time_limit <= 1e9)))
    broken("relaxation steps or time limit out of their domain");
  if(!(o.target_vertices == 0 || in(double(o.target_vertices), 4, 1e9)) ||
     !(o.max_vertices == 0 || in(double(o.max_vertices), 1, 1e10)))
    broken("a vertex count out of its domain");
  if(o.output_kind != "dual" && o.output_kind != "primal")
    broken("output " + quote(o.output_kind));
  if(o.placement != "qem" && o.placement != "sharp" && o.placement != "average")
    broken("placement " + quote(o.placement));
}

void run_one(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> arguments = arguments_of(data, size);
  std::vector<char*> argv;
  for(std::string& argument : arguments)
    argv.push_back(argument.data());
  argv.push_back(nullptr);
  const int argc = int(arguments.size());
  try {
    check_accepted(parse_arguments(argc, argv.data()), argc);
  } catch(const Failure& failure) {
    check_refusal(failure);
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
  return replay_files(argc, argv, "fuzz_options", run_one);
}
#endif
