// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_STATISTICS_H
#define CGAL_RANGE_SPACE_REMESHING_STATISTICS_H

#include <cstddef>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

What a run of `primal_remesh()` did. Times are wall-clock milliseconds of the
algorithm alone (no file input/output).
*/
struct Statistics
{
  std::size_t input_vertices = 0;
  std::size_t input_faces = 0;
  /// input vertices on which the range map was evaluated (the map is lazy)
  std::size_t mapped_vertices = 0;
  /// input triangles visited by the seeding and the arc tracing
  std::size_t visited_faces = 0;
  /// intersection vertices found (surface ∩ grid edges)
  std::size_t intersection_vertices = 0;
  /// triangle-to-triangle steps made by the arc tracer
  std::size_t tracing_steps = 0;
  std::size_t output_vertices = 0;
  std::size_t output_edges = 0;
  std::size_t output_faces = 0;
  /// faces of degree 2 merged into one edge (their two vertices get valence 3)
  std::size_t digons = 0;
  /// faces of degree 2 between an arc and a boundary edge (the border crosses a
  /// hyperplane and comes straight back), merged into one boundary edge: their two
  /// boundary vertices get valence 2
  std::size_t boundary_digons = 0;
  /// input vertices added as boundary vertices where a border cycle crosses the grid
  /// hyperplanes only twice (a polygon mesh cannot have a hole of two edges); they
  /// have valence 2
  std::size_t boundary_corners = 0;
  /// border cycles of the input that no grid hyperplane crosses (a hole inside one
  /// cell): the output has no boundary for them, the face of the cell covers the hole.
  /// The complete scan counts them all; the seeded traversal only those of components
  /// in which it found nothing to trace (it never sees the others).
  std::size_t uncrossed_border_cycles = 0;
  /// output faces whose boundary visited a vertex twice, split by a chord
  std::size_t non_simple_faces = 0;
  /// output pieces too small to form a polygon mesh (fewer than 4 vertices), dropped
  std::size_t dropped_pieces = 0;
  /// edges joining the same two vertices as another edge (where a part of the surface
  /// thinner than a cell crosses a grid hyperplane, the faces of the cells on either
  /// side share two corners), split at a point of their arc by a vertex of valence 2:
  /// a face-list file (OFF, OBJ, PLY, STL) could not tell the two edges apart (it
  /// would read them back as one edge of four faces)
  std::size_t split_parallel_edges = 0;
  /// parallel edges left in the output (an edge with no arc to split it on: a chord
  /// of a split face, a border edge); `out` keeps them apart, a face-list file cannot
  std::size_t parallel_edges = 0;
  /// number of seeds the traversal started from (SEEDED) or vertices scanned (COMPLETE_SCAN)
  std::size_t seeds = 0;

  /// the cell size of the run (smaller than the one asked for when
  /// `preserve_topology` had to refine it)
  double cell_size = 0;
  /// \name Topology
  /// Filled when the named parameter `check_topology` (or `preserve_topology`) is
  /// set, by the complete scan only (see `Topology_defect_kind`).
  /// @{

  /// whether the check ran
  bool topology_checked = false;
  /// closed curves where the surface meets a grid hyperplane without reaching a
  /// grid edge: no arc traces them
  std::size_t closed_loops = 0;
  /// closed loops that only cut a disk-shaped cap off the surface (the surface
  /// pokes through a grid face without reaching a grid edge, typically where it
  /// touches a grid plane): the output, covering it by the face of the cell on the
  /// other side, keeps the topology; not counted in `closed_loops`
  std::size_t harmless_loops = 0;
  /// cells where the surface is not a set of disks each bounded by one traced cycle
  std::size_t non_disk_cells = 0;
  /// input components that give no output
  std::size_t lost_components = 0;
  /// V - E + F of the input
  long input_euler_characteristic = 0;
  /// V - E + F of the output
  long output_euler_characteristic = 0;
  /// connected components of the input
  std::size_t input_components = 0;
  /// connected components of the output
  std::size_t output_components = 0;
  /// times `preserve_topology` reduced the cell size before the check passed (in
  /// `remesh()`, those for the dual too)
  std::size_t topology_refinements = 0;
  /// rounds of `refine_around_defects` before the run reported: each magnified the
  /// map around the defects the last run left (0: f itself)
  std::size_t local_refinements = 0;
  /// regions of the range space where the reported run magnified f
  std::size_t magnified_regions = 0;
  /// the largest magnification of f in them (1 without)
  double largest_magnification = 1;
  /// time of the check (of the last run, with `preserve_topology`)
  double time_topology_ms = 0;
  /// whether the check ran and found nothing: then every region of the surface in a
  /// cell is a disk bounded by one output face, and the output is a cell
  /// decomposition of the input (the same topology, component by component)
  bool topology_preserved() const
  {
    return topology_checked && closed_loops == 0 && non_disk_cells == 0 && lost_components == 0 &&
           uncrossed_border_cycles == 0 && dropped_pieces == 0;
  }
  /// @}

  double time_seeding_ms = 0;
  double time_tracing_ms = 0;
  double time_faces_ms = 0;
  double time_output_ms = 0;
  double time_total_ms = 0;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef
What a run of `dualize()` did.
*/
struct Dual_statistics
{
  std::size_t dual_vertices = 0;
  std::size_t dual_faces = 0;
  std::size_t quads = 0;
  /// pairs of triangles (duals of the two valence-3 ends of a merged digon) joined into a quad
  std::size_t joined_triangle_pairs = 0;
  /// faces that are not quads (duals of primal vertices of valence other than 4 that
  /// could not be paired, faces joined across parallel edges); `remesh()` makes them
  /// quads next (`All_quads_statistics`)
  std::size_t non_quads = 0;
  /// pieces whose dual cannot be a polygon mesh (e.g. a pillow of two faces whose
  /// vertices all have valence 2), removed
  std::size_t dropped_pieces = 0;
  /// pairs of distinct edges joining the same two vertices left in the dual (where two
  /// primal faces share two edges, at coarse cell sizes; pinches are removed, one edge
  /// of a pair between quads is rotated inside them, and a pair neither undoes is
  /// joined, see below; this counts the pairs left, which none of that undid): valid
  /// in the halfedge structure, but a file format that stores faces as vertex lists
  /// cannot keep them apart
  std::size_t parallel_edges = 0;
  /// pinches removed: where two primal faces share two edges with a digon between them,
  /// the dual has two triangles around a vertex of valence 2 between two parallel edges;
  /// that disk is removed and the two edges glued into one (the topology is kept)
  std::size_t removed_pinches = 0;
  /// pairs of parallel edges that neither a pinch removal nor a rotation undoes, one of
  /// whose edges is removed by joining its two faces into one (a face with more corners,
  /// counted in `non_quads`)
  std::size_t joined_parallel_edges = 0;
  double time_ms = 0;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef
What the stage of `remesh()` that makes the dual all quads did (after `dualize()`,
before the collapse). The dual's faces that are not quads (where parallel edges were
joined, pinches glued, pieces dropped) are turned into quads with operations that keep
the vertices, the Euler characteristic and the components: a face of more than four
sides is cut by diagonals into quads and, if its degree is odd, one triangle; each
triangle then walks along a shortest path of quads to the nearest other triangle (a
quad at a time: joined with the quad into a pentagon, which is cut again so that the
triangle is on the far side) and the two are joined into a quad. Of the diagonals a
step can take, it takes the one whose faces are in the best shape (not folded, then
convex, then by the least corner angle); the relaxation and the untangling that
follow clean the shapes.

A piece with border can have an odd number of faces of odd degree (as many as its
border edges, modulo 2), and a piece of two triangles glued back to back has no room
for a quad: their faces stay, counted in `non_quads_after` and
`pieces_not_all_quads`, and `Remesh_statistics::topology_preserved()` is false: such
a piece cannot be all quads at this cell size.
*/
struct All_quads_statistics
{
  /// faces of the dual that were not quads
  std::size_t non_quads_before = 0;
  /// diagonals that cut faces of more than four sides
  std::size_t split_faces = 0;
  /// steps of a triangle through a quad towards its partner
  std::size_t triangle_steps = 0;
  /// pairs of triangles joined into a quad
  std::size_t joined_triangles = 0;
  /// faces still not quads: a triangle without a partner in its piece, or one that
  /// every path refused (a step would have doubled an edge or made a face visit a
  /// vertex twice)
  std::size_t non_quads_after = 0;
  /// connected pieces of the output that hold the faces of `non_quads_after`: pieces
  /// with border and an odd number of faces of odd degree, or pieces too small to be
  /// all quads (two triangles glued back to back, which coarse cells leave around thin
  /// parts)
  std::size_t pieces_not_all_quads = 0;
  double time_ms = 0;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef
What a run of `collapse_quads()` did.
*/
struct Collapse_statistics
{
  /// quads collapsed along a diagonal (each removes one face and one vertex)
  std::size_t collapsed_quads = 0;
  /// vertices of valence 2 dissolved before and after the passes, each merging its two
  /// quads into one (each also removes one face and one vertex)
  std::size_t removed_doublets = 0;
  /// edges between two quads turned to join the other corners of the two (each lowers
  /// the valence energy and keeps all counts)
  std::size_t rotated_edges = 0;
  /// rotations that keep the valence energy, each kept only because the collapse or
  /// rotation it made possible then lowered it (the pair moved a valence 3-5 dipole
  /// onto another one); the operations they made possible are counted above
  std::size_t neutral_rotations = 0;
  /// passes: the first over all quads, each next one over the quads around the vertices
  /// that the previous pass changed; when one changes nothing, a walk of the dipoles
  /// (one more pass, if edges rotate); until a walk keeps nothing or the limit is hit
  std::size_t passes = 0;
  /// collapses and rotations that would lower the valence energy but were refused
  /// because the result would not be a valid manifold (link condition, doublet),
  /// summed over the passes
  std::size_t refused_topology = 0;
  /// ... refused because a face around the merged vertex would fold over (or, for a
  /// rotation, a new quad would face the other way, or stop being convex)
  std::size_t refused_fold_over = 0;
  double time_ms = 0;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef
What the untangling at the end of `remesh()` did. A face is folded when its vector
area faces against the sum of its corners' unit normals, non-convex when it is not
folded but some corner turns against its vector-area normal: at a corner with sides
e_next and e_prev, (e_next x e_prev) . n <= 0. The untangling moves only the vertices
of such faces (and, where that is not enough, the vertices around them), on their
tangent planes, never making a face's shape worse.
*/
struct Untangle_statistics
{
  /// folded faces when the stage began (after the relaxation)
  std::size_t folded_before = 0;
  /// non-convex faces when the stage began
  std::size_t non_convex_before = 0;
  /// folded faces in the output
  std::size_t folded_after = 0;
  /// non-convex faces in the output
  std::size_t non_convex_after = 0;
  /// vertex moves made (a vertex may move once per round)
  std::size_t moves = 0;
  /// rounds over the vertices of the faces still folded or non-convex
  std::size_t rounds = 0;
  /// vertices tried: for each, a search of places on its tangent planes
  std::size_t tries = 0;
  /// vertices of the mesh when the stage began: the moves try at most three times as many
  std::size_t vertices_before = 0;
  /// quads collapsed along a diagonal where moves left them tangled (each where the
  /// faces it changes are then less tangled: fewer non-convex, then fewer folded)
  std::size_t collapses = 0;
  /// edges of such quads rotated, where no collapse was allowed
  std::size_t rotations = 0;
  /// moves of the last run, for the faces still tangled after those: off the tangent
  /// planes along the vertex normal, by at most a tenth of the mean length of the
  /// vertex's edges (the input folds there, or bends more than the quads can follow)
  std::size_t moves_off_surface = 0;
  double time_ms = 0;
};

/// What `insert_crease_triangles()` did.
struct Crease_statistics
{
  /// edges taken as creases
  std::size_t feature_edges = 0;
  /// vertices on creases, duplicated once per smooth sector around them
  std::size_t added_vertices = 0;
  /// zero-area triangles along the creases and at their corners
  std::size_t crease_triangles = 0;
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_STATISTICS_H
