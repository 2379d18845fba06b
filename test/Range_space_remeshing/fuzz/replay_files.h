// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a fuzz target built without libFuzzer does: replay the files given on its
// command line (its seed corpus and the reproducers of past findings), as a ctest.

#ifndef RANGE_SPACE_REMESHING_TEST_FUZZ_REPLAY_FILES_H
#define RANGE_SPACE_REMESHING_TEST_FUZZ_REPLAY_FILES_H

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

/// Runs `run_one` on the bytes of each file argv[1..]; 2 if one cannot be read.
inline int replay_files(int argc, char** argv, const char* target, void (*run_one)(const std::uint8_t*, std::size_t))
{
  for(int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if(!in) {
      std::cerr << target << ": cannot read " << argv[i] << std::endl;
      return 2;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    run_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << target << ": replayed " << argc - 1 << " inputs" << std::endl;
  return 0;
}

#endif // RANGE_SPACE_REMESHING_TEST_FUZZ_REPLAY_FILES_H
