// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PROGRESS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PROGRESS_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The user's `progress_visitor`, told how far a stage has come; throws
/// `Remeshing_cancelled` when the visitor returns false. Loops report every
/// `interval` elements (`report_every()`): a few microseconds of work or less per
/// element, so the visitor hears from a run far more often than every 50 ms, and the
/// call (through `std::function`, kept out of the engines' template parameters) costs
/// nothing measurable.
class Progress
{
public:
  static constexpr std::size_t interval = 4096;

  Progress() = default;
  template <class Visitor>
  explicit Progress(Visitor visitor) : visitor_(std::move(visitor))
  {}

  /// Tells the visitor that `fraction` (0 to 1) of `stage` is done.
  void report(Remeshing_stage stage, double fraction) const
  {
    if(visitor_ && !visitor_(stage, fraction))
      throw Remeshing_cancelled();
  }

  /// `report()` of `fraction`, when `index` is a multiple of `interval`.
  void report_at_every(Remeshing_stage stage, std::size_t index, double fraction) const
  {
    if(index % interval == 0 && visitor_)
      report(stage, fraction);
  }

  /// What the visitor answers (true without one): a run hands its progress to the
  /// functions it calls as their visitor.
  bool operator()(Remeshing_stage stage, double fraction) const { return !visitor_ || visitor_(stage, fraction); }

  /// `report()` of `done` elements of `total`, when `done` is a multiple of `interval`.
  void report_every(Remeshing_stage stage, std::size_t done, std::size_t total) const
  {
    if(done % interval == 0 && visitor_)
      report(stage, total > 0 ? double(done) / double(total) : 1.0);
  }

  /// The progress without a visitor, for engines run without one.
  static const Progress& none()
  {
    static const Progress nobody;
    return nobody;
  }

private:
  std::function<bool(Remeshing_stage, double)> visitor_;
};

/// For a loop whose elements cost unequal work (a face crossing thousands of cells,
/// an arc crossing thousands of faces): reports each time another `Progress::interval`
/// units of work have been done, so that the visitor hears from it as often whatever the
/// elements cost.
class Work_meter
{
public:
  Work_meter(const Progress& progress, Remeshing_stage stage) : progress_(progress), stage_(stage) {}

  /// Counts `units` of work done; `fraction` (a number, or a callable giving it) is
  /// how far the stage is, evaluated only when reported: the loops that count are the
  /// engines' innermost.
  template <class Fraction>
  void add(std::size_t units, const Fraction& fraction)
  {
    work_ += units;
    if(work_ >= next_report_) {
      next_report_ = work_ + Progress::interval;
      if constexpr(std::is_invocable_v<Fraction>)
        progress_.report(stage_, fraction());
      else
        progress_.report(stage_, fraction);
    }
  }

private:
  const Progress& progress_;
  Remeshing_stage stage_;
  std::size_t work_ = 0, next_report_ = 0;
};

/// The `progress_visitor` of `np`, if any.
template <class NamedParameters>
Progress progress_of(const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::progress_visitor_t>::value)
    return Progress();
  else
    return Progress(CGAL::parameters::get_parameter(np, internal_np::progress_visitor));
}

/// Removes every element of `g`, keeping the property maps the caller may hold
/// (`CGAL::clear()` removes those of a `Surface_mesh`).
template <class Graph>
auto remove_all_elements(Graph& g, int) -> decltype(g.clear_without_removing_property_maps())
{
  g.clear_without_removing_property_maps();
}
template <class Graph>
void remove_all_elements(Graph& g, long)
{
  CGAL::clear(g);
}
template <class Graph>
void remove_all_elements(Graph& g)
{
  remove_all_elements(g, 0);
}

/// `run()`, after which `mesh` is left empty if the run was cancelled: around a stage
/// whose other errors are refusals of the parameters, which leave the output as it was.
template <class Mesh, class Run>
auto emptied_on_cancel(Mesh& mesh, const Run& run)
{
  try {
    return run();
  } catch(const Remeshing_cancelled&) {
    remove_all_elements(mesh);
    throw;
  }
}

/// `run()`, after which `mesh` is left empty if the run threw (was cancelled, refused
/// its input, ran out of memory): an output mesh never holds a partial remesh, nor the
/// last trial of a search that failed.
template <class Mesh, class Run>
auto emptied_on_failure(Mesh& mesh, const Run& run)
{
  try {
    return run();
  } catch(...) {
    remove_all_elements(mesh);
    throw;
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PROGRESS_H
