// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H
#define CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H

#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

Thrown by the functions of the package when they cannot do what is asked. `what()`
names the problem in one line; `kind()` tells the caller what to do about it.
*/
class Remeshing_error : public std::runtime_error
{
public:
  /// What went wrong.
  enum class Kind
  {
    /// The input is unusable: an empty mesh, a face that is not a triangle, a border
    /// where a closed surface is required (`insert_crease_triangles()`), a NaN or
    /// infinite coordinate or map value, a soup that cannot be made a mesh.
    BAD_INPUT,
    /// A parameter is out of its domain: a non-positive or non-finite cell size, a
    /// non-finite grid origin, a sizing field not positive and finite, an impossible
    /// camera, parameters that exclude each other.
    BAD_PARAMETER,
    /// The output would exceed the cap on its vertices (`maximum_number`), or the grid
    /// is so fine that range coordinates would overflow: a larger cell size is needed.
    OUTPUT_TOO_LARGE,
    /// `preserve_topology`: no cell size tried keeps the input's topology.
    TOPOLOGY_NOT_PRESERVED,
    /// `number_of_target_vertices`: no cell size tried gives the count within 10%.
    TARGET_NOT_REACHED,
    /// The `progress_visitor` asked to stop (the exception is a `Remeshing_cancelled`).
    CANCELLED
  };

  explicit Remeshing_error(const std::string& message, Kind kind = Kind::BAD_INPUT)
    : std::runtime_error(message), kind_(kind)
  {}

  /// What went wrong.
  Kind kind() const { return kind_; }

private:
  Kind kind_;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef

Thrown when the `progress_visitor` returns `false`. The function's output mesh is then
left empty (see each function).
*/
class Remeshing_cancelled : public Remeshing_error
{
public:
  Remeshing_cancelled() : Remeshing_error("the run was cancelled", Kind::CANCELLED) {}

  /// cancelled while `preserve_topology` refined the cell size, in its refinement
  /// number `refinements`; `finest_cell_size`, the finest run to the end, had defects
  Remeshing_cancelled(std::size_t refinements, double finest_cell_size)
    : Remeshing_error(message_after(refinements, finest_cell_size), Kind::CANCELLED),
      refinements_(refinements), finest_cell_size_(finest_cell_size)
  {}

  /// the refinement of `preserve_topology` cancelled (0: the first run)
  std::size_t refinements() const { return refinements_; }
  /// the finest cell size run to the end before the cancel (0: the first run)
  double finest_cell_size() const { return finest_cell_size_; }

private:
  static std::string message_after(std::size_t refinements, double finest_cell_size)
  {
    std::ostringstream message; // cell sizes in map units can be far below 1e-6
    message << std::setprecision(3) << "the run was cancelled after " << refinements
            << " refinement(s) of preserve_topology; at cell size " << finest_cell_size
            << ", the finest run to the end, the topology was not preserved";
    return message.str();
  }

  std::size_t refinements_ = 0;
  double finest_cell_size_ = 0;
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H
