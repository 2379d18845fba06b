// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: what the program does while the remesh runs. The progress line
// on a terminal, --time-limit, and Ctrl-C (SIGINT), which cancels the run and leaves
// no file behind.

#ifndef RANGE_SPACE_REMESHING_TOOLS_PROGRESS_H
#define RANGE_SPACE_REMESHING_TOOLS_PROGRESS_H

#include "mesh_file_writer.h"
#include "mesh_types.h"
#include "options.h"

#include <CGAL/Range_space_remeshing/remesh.h>

#include <chrono>
#include <csignal>
#include <cstdio>

#include <unistd.h>

namespace rsr_program {

/// Set by Ctrl-C (SIGINT): the progress visitor then cancels the remesh, and the
/// program checks it again after the remesh and before the files are renamed.
inline volatile std::sig_atomic_t interrupted = 0;

/// Set as the files start to be renamed into place: a Ctrl-C from then on comes too
/// late and is ignored, as the run ends with its files written and exit 0.
inline volatile std::sig_atomic_t committing = 0;

/// What an interrupted run says on stderr, whenever Ctrl-C came.
inline constexpr char interrupted_line[] = "range_space_remesh: interrupted: nothing was written\n";
inline constexpr int interrupted_status = 130; // 128 + SIGINT, as the shells report it

extern "C" inline void cancel_on_interrupt(int)
{
  if(committing)
    return;
  // while files are written (or at a second Ctrl-C, as when the reading takes long),
  // stop here: remove the temporary files, say so, exit; all async-signal-safe
  if(rsr_io::internal::has_pending_files() || interrupted) {
    rsr_io::internal::remove_pending_files();
    const ssize_t written = ::write(STDERR_FILENO, interrupted_line, sizeof interrupted_line - 1);
    static_cast<void>(written);
    ::_exit(interrupted_status);
  }
  interrupted = 1;
}

/// Thrown where the program checks for a Ctrl-C the remesh did not see.
struct Interrupted
{};

inline void stop_if_interrupted()
{
  if(interrupted)
    throw Interrupted();
}

/// The program's progress visitor: a progress line on stderr when it is a terminal
/// and the run takes more than a second (not with --quiet), --time-limit, and Ctrl-C,
/// which cancel the run.
class Progress_line
{
public:
  explicit Progress_line(const Options& options)
    : limit_(options.time_limit), show_(!options.quiet && ::isatty(STDERR_FILENO))
  {}

  bool operator()(RSR::Remeshing_stage stage, double fraction)
  {
    if(interrupted)
      return false;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if(limit_ > 0 && elapsed > limit_) {
      timed_out_ = true;
      return false;
    }
    if(show_ && elapsed > 1 && elapsed - last_shown_ >= 0.1) {
      std::fprintf(stderr, "\rrange_space_remesh: %-14s %3d%%", RSR::stage_name(stage), int(100 * fraction));
      std::fflush(stderr);
      last_shown_ = elapsed;
      shown_ = true;
    }
    return true;
  }

  /// Removes the progress line, if one was shown.
  void clear()
  {
    if(shown_)
      std::fputs("\r\033[K", stderr);
    shown_ = false;
  }

  bool timed_out() const { return timed_out_; }
  double limit() const { return limit_; }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double limit_;
  bool show_;
  double last_shown_ = 0;
  bool shown_ = false, timed_out_ = false;
};

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_PROGRESS_H
