// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: how the program fails. Every refusal is one Failure, which
// main() prints as one line on stderr and turns into exit status 2.

#ifndef RANGE_SPACE_REMESHING_TOOLS_FAILURE_H
#define RANGE_SPACE_REMESHING_TOOLS_FAILURE_H

#include <cstdio>
#include <string>

namespace rsr_program {

struct Failure
{
  std::string message;
};

[[noreturn]] inline void fail(const std::string& message) { throw Failure{message}; }

/// `text` with its control characters (a newline) escaped: a message holding it stays
/// one line.
inline std::string escaped(const std::string& text)
{
  std::string out;
  for(const unsigned char c : text) {
    if(c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", unsigned(c));
      out += escaped;
    } else {
      out += char(c);
    }
  }
  return out;
}

/// `text` between quotes, escaped: what a message quotes from the command line or a file.
inline std::string quote(const std::string& text) { return "'" + escaped(text) + "'"; }

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_FAILURE_H
