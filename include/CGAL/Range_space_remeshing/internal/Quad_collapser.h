// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H

// The quad collapse of section 6 of the paper, on any MutableFaceGraph: which quads
// to collapse, which edges to rotate, in which order (the operations themselves and
// their tests are Quad_operations.h's).
//
// The collapses are interleaved with edge rotations (Tarini et al., Practical quad mesh
// simplification, 2010): the edge u-v between the quads (u, v, f1, f2) and
// (v, u, g1, g2) is turned to join f1-g1 or f2-g2, the other diagonals of the hexagon
// the two quads form. u and v lose an edge, the new ends gain one; no vertex moves and
// the counts stay, so a rotation evens out valences where no collapse can (a 5 beside
// a 3 that is not across a quad from another 3). When neither lowers the energy any
// more, rotations that keep it move the remaining 3-5 pairs (dipoles) one step, where a
// collapse or a rotation then cancels them (`walk_dipoles()`).

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Quad_operations.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class PolygonMesh, class VertexPointMap, class TangentPlanesMap, class ConstrainedMap,
          class VertexIndexMap, class FaceIndexMap>
class Quad_collapser
    : Quad_operations<PolygonMesh, VertexPointMap, TangentPlanesMap, ConstrainedMap, VertexIndexMap, FaceIndexMap>
{
  using Operations =
      Quad_operations<PolygonMesh, VertexPointMap, TangentPlanesMap, ConstrainedMap, VertexIndexMap, FaceIndexMap>;
  using typename Operations::GT;
  using typename Operations::vertex_descriptor;
  using typename Operations::halfedge_descriptor;
  using typename Operations::face_descriptor;
  using Operations::mesh_;
  using Operations::face_index_;
  using Operations::removed_faces_;
  using Operations::index;
  using Operations::position;
  using Operations::valence;
  using Operations::on_border;
  using Operations::regular_valence;
  using Operations::lowest_valence;
  using Operations::null_halfedge;
  using Operations::is_quad;
  using Operations::is_live_quad;
  using Operations::hexagon_around;
  using Operations::rotation_keeps_manifold;
  using Operations::rotation_keeps_faces_unfolded;
  using Operations::keeps_manifold;
  using Operations::merged_position;
  using Operations::keeps_faces_unfolded;
  using Operations::remove_doublets;
  using Operations::remove_unlinked_elements;

  /// A quad worth collapsing, by how much its better diagonal lowers the energy; or,
  /// with an `edge` (a halfedge of `quad`), an edge worth rotating.
  struct Candidate
  {
    int energy_decrease;
    // tie-breaks, for determinism: the quad's position in the face sweep, then 0 for
    // its collapse, `rank_in_quad()` of the edge for a rotation (see collect_candidates())
    std::size_t order;
    std::size_t rank_in_quad;
    face_descriptor quad;
    halfedge_descriptor edge;
  };

public:
  /// `normals` holds unit normals by vertex index; merged vertices' are updated.
  Quad_collapser(PolygonMesh& mesh, VertexPointMap vpm, TangentPlanesMap planes,
                 ConstrainedMap constrained, VertexIndexMap vertex_index, FaceIndexMap face_index,
                 std::vector<Vec3>& normals, bool rotate_edges)
    : Operations(mesh, vpm, planes, constrained, vertex_index, face_index, normals), rotate_edges_(rotate_edges),
      touched_in_pass_(removed_faces_.size(), 0), changed_in_walk_(removed_faces_.size(), 0),
      nearby_in_stamp_(removed_faces_.size(), 0)
  {}

  /// Passes over the quads: the first over all of them, each next one over the quads
  /// whose vertex valences the previous pass changed (the others' energies are as
  /// they were). Once a pass changes nothing, and if edges rotate, a pass walks the
  /// dipoles (`walk_dipoles()`); what it changes starts the passes again.
  Collapse_statistics run(int maximum_passes, const Progress& progress)
  {
    progress_ = &progress;
    maximum_passes_ = maximum_passes;
    try {
      return run_passes();
    } catch(const Remeshing_cancelled&) {
      remove_unlinked_elements(); // each collapse and rotation is whole: the mesh is valid
      throw;
    }
  }

private:
  /// Tells the visitor that the passes before this one are done.
  void report_pass() const
  {
    progress_->report(Remeshing_stage::COLLAPSE, double(pass_ - 1) / double(maximum_passes_));
  }

  Collapse_statistics run_passes()
  {
    Collapse_statistics stats;
    std::vector<Candidate> candidates;
    stats.removed_doublets = remove_doublets();
    progress_->report(Remeshing_stage::COLLAPSE, 0);
    std::vector<face_descriptor> to_examine;
    for(face_descriptor f : faces(mesh_))
      if(!removed_faces_[get(face_index_, f)])
        to_examine.push_back(f);
    for(int pass = 1; pass <= maximum_passes_; ++pass) {
      const bool walk = to_examine.empty();
      if(walk && !rotate_edges_)
        break;
      pass_ = pass;
      report_pass();
      ++stats.passes;
      touched_ = &to_examine;
      if(walk) {
        if(walk_dipoles(stats) == 0)
          break;
      } else {
        collect_candidates(to_examine, candidates);
        report_pass();
        sort_for_sweep(candidates);
        report_pass();
        to_examine.clear();
        for(std::size_t c = 0; c < candidates.size(); ++c) {
          progress_->report_every(Remeshing_stage::COLLAPSE, std::size_t(pass - 1) * candidates.size() + c,
                                  std::size_t(maximum_passes_) * candidates.size());
          try_candidate(candidates[c], stats);
        }
      }
      std::sort(to_examine.begin(), to_examine.end(), [&](face_descriptor f, face_descriptor g) {
        return get(face_index_, f) < get(face_index_, g);
      });
    }
    // the passes' collapses and rotations change the valences and places around the
    // doublets the first sweep had to leave (a border corner of valence 2 beside one, a
    // merged quad that would fold): they may go now
    stats.removed_doublets += remove_doublets();
    progress_->report(Remeshing_stage::COLLAPSE, 1);
    remove_unlinked_elements();
    return stats;
  }

  /// The collapses and rotations of the quads of `quads` that lower the valence energy
  /// (the caller orders them).
  void collect_candidates(const std::vector<face_descriptor>& quads, std::vector<Candidate>& candidates)
  {
    candidates.clear();
    std::size_t order = 0;
    for(face_descriptor f : quads) {
      if(!is_live_quad(f))
        continue;
      // the corners are read once for the quad's six operations: this loop is most of
      // the cost of the passes and of the dipole walk's tries
      const Corners corners = corners_from(halfedge(f, mesh_));
      // which of a and c survives changes nothing in the decrease: no tie-break yet
      const int decrease = (std::max)(corners.collapse_decrease(0), corners.collapse_decrease(1));
      if(decrease > 0)
        candidates.push_back({decrease, order, 0, f, null_halfedge()});
      if(rotate_edges_) // an edge between two examined quads is listed twice; the second finds it done
        for(int i = 0; i < 4; ++i) {
          const int rotation_decrease = best_rotation(corners.side[i], corners.loss_of_side_ends(i)).energy_decrease;
          if(rotation_decrease > 0)
            candidates.push_back({rotation_decrease, order, rank_in_quad(corners.side[i]), f, corners.side[i]});
        }
      ++order;
    }
  }

  /// Sorts a pass's candidates by `comes_before_in_sweep()`. They arrive in sweep
  /// order, so grouping them by `has_priority()`'s classes with a stable counting sort
  /// keeps the sweep order within each class; only the rotations of one quad (at most
  /// four, side by side) can be left out of rank order, which an insertion sort mends
  /// in linear time, where a comparison sort compares the first pass's candidates
  /// about a million times on a large input (see benchmark/RESULTS.md).
  void sort_for_sweep(std::vector<Candidate>& candidates)
  {
    if(!group_by_priority_class(candidates)) {
      std::sort(candidates.begin(), candidates.end(), comes_before_in_sweep);
      return;
    }
    for(std::size_t i = 1; i < candidates.size(); ++i) {
      if(!comes_before_in_sweep(candidates[i], candidates[i - 1]))
        continue;
      const Candidate moved = candidates[i];
      std::size_t j = i;
      for(; j > 0 && comes_before_in_sweep(moved, candidates[j - 1]); --j)
        candidates[j] = candidates[j - 1];
      candidates[j] = moved;
    }
  }

  /// Stable counting sort by priority class: a larger decrease first, then collapses
  /// before rotations. Returns false, leaving the list as it is, if there would be more
  /// classes than candidates (huge decreases around vertices of huge valence).
  bool group_by_priority_class(std::vector<Candidate>& candidates)
  {
    int largest = 0;
    for(const Candidate& c : candidates)
      largest = (std::max)(largest, c.energy_decrease);
    const std::size_t classes = 2 * std::size_t(largest) + 2;
    if(classes > 2 * candidates.size() + 16)
      return false;
    auto priority_class = [largest](const Candidate& c) {
      return 2 * std::size_t(largest - c.energy_decrease) + (c.edge == null_halfedge() ? 0 : 1);
    };
    class_starts_.assign(classes + 1, 0);
    for(const Candidate& c : candidates)
      ++class_starts_[priority_class(c) + 1];
    for(std::size_t k = 1; k <= classes; ++k)
      class_starts_[k] += class_starts_[k - 1];
    grouped_candidates_.resize(candidates.size());
    for(const Candidate& c : candidates)
      grouped_candidates_[class_starts_[priority_class(c)]++] = c;
    candidates.swap(grouped_candidates_);
    return true;
  }

  /// The order of a pass: `has_priority()`, then the quads' order in the sweep, then
  /// `rank_in_quad()`.
  static bool comes_before_in_sweep(const Candidate& x, const Candidate& y)
  {
    if(has_priority(x, y) || has_priority(y, x))
      return has_priority(x, y);
    if(x.order != y.order)
      return x.order < y.order;
    return x.rank_in_quad < y.rank_in_quad;
  }

  /// Whether x goes before y whatever the tie-breaks: a larger decrease, and at equal
  /// decrease a collapse first (a rotation can take the valence-3 vertex a collapse
  /// needs, and leave two irregular vertices where the collapse left none).
  static bool has_priority(const Candidate& x, const Candidate& y)
  {
    if(x.energy_decrease != y.energy_decrease)
      return x.energy_decrease > y.energy_decrease;
    return x.edge == null_halfedge() && y.edge != null_halfedge();
  }

  /// Ties between operations are broken by where the vertices are, not by vertex
  /// indices nor by halfedge(quad): those differ between mesh types (a `Polyhedron_3`
  /// copy of a `Surface_mesh` numbers its vertices in another order), the points do not.
  bool comes_before(vertex_descriptor x, vertex_descriptor y) const
  {
    const Vec3 p = position(x), q = position(y);
    return p < q || (p == q && index(x) < index(y)); // the index only for coincident points
  }

  /// The halfedge h0 = a->b of the quad whose collapse (c into a) lowers the energy
  /// most; a tie, and which of a and c survives, go by `comes_before()`.
  halfedge_descriptor better_diagonal(face_descriptor quad) const
  {
    auto from_first = [this](halfedge_descriptor h0) { // the same diagonal from a or from c
      const halfedge_descriptor h2 = next(next(h0, mesh_), mesh_);
      return comes_before(source(h0, mesh_), source(h2, mesh_)) ? h0 : h2;
    };
    const halfedge_descriptor h = halfedge(quad, mesh_);
    const halfedge_descriptor x = from_first(h), y = from_first(next(h, mesh_));
    const int x_decrease = energy_decrease(x), y_decrease = energy_decrease(y);
    if(x_decrease != y_decrease)
      return x_decrease > y_decrease ? x : y;
    return comes_before(source(x, mesh_), source(y, mesh_)) ? x : y;
  }

  /// 1 + the rank of h's source among the quad's corners, by `comes_before()`.
  std::size_t rank_in_quad(halfedge_descriptor h) const
  {
    std::size_t rank = 1;
    for(vertex_descriptor w : CGAL::vertices_around_face(h, mesh_))
      rank += comes_before(w, source(h, mesh_));
    return rank;
  }

  /// Queues the faces around v for the next pass (once each).
  void touch_faces_around(vertex_descriptor v)
  {
    if(!touching_)
      return;
    for(face_descriptor g : CGAL::faces_around_target(halfedge(v, mesh_), mesh_)) {
      if(g == boost::graph_traits<PolygonMesh>::null_face())
        continue; // around a border vertex
      const std::size_t i = get(face_index_, g);
      if(touched_in_pass_[i] != pass_) {
        touched_in_pass_[i] = pass_;
        touched_->push_back(g);
      }
      if(changed_in_walk_[i] != walks_ + 1) {
        changed_in_walk_[i] = walks_ + 1;
        changed_since_walk_.push_back(g);
      }
    }
  }

  /// The four sides of a quad from h0 on, with their sources' valences and regular
  /// valences: what the energy changes of its collapses and rotations are made of.
  /// Each corner's energy and loss are computed once: a quad's six operations use them
  /// sixteen times, and this is the inner loop of the passes and of the dipole walk.
  struct Corners
  {
    std::array<halfedge_descriptor, 4> side; // side[i] runs from corner i to corner i + 1
    std::array<int, 4> valence, regular;
    std::array<int, 4> energy_of, loss_of; // energy(i), edge_loss_decrease(i)

    static int energy(int valence, int regular) { return (valence - regular) * (valence - regular); }
    /// Decrease of a vertex's energy when it loses one edge: (v - r)^2 - (v - 1 - r)^2.
    static int edge_loss_decrease(int valence, int regular) { return 2 * (valence - regular) - 1; }
    void set(int i, halfedge_descriptor h, int corner_valence, int corner_regular)
    {
      side[i] = h;
      valence[i] = corner_valence;
      regular[i] = corner_regular;
      energy_of[i] = energy(corner_valence, corner_regular);
      loss_of[i] = edge_loss_decrease(corner_valence, corner_regular);
    }
    /// Decrease of the energy of the four corners when corner i + 2 is merged into i.
    int collapse_decrease(int i) const
    {
      const int a = i, b = (i + 1) % 4, c = (i + 2) % 4, d = (i + 3) % 4;
      return energy_of[a] + energy_of[c] - energy(valence[a] + valence[c] - 2, regular[a]) + loss_of[b] +
             loss_of[d];
    }
    /// Decrease of the energy of side i's ends when the side is rotated away.
    int loss_of_side_ends(int i) const { return loss_of[i] + loss_of[(i + 1) % 4]; }
  };

  Corners corners_from(halfedge_descriptor h0) const
  {
    Corners corners;
    halfedge_descriptor h = h0;
    for(int i = 0; i < 4; ++i, h = next(h, mesh_)) {
      const vertex_descriptor w = source(h, mesh_);
      corners.set(i, h, valence(w), regular_valence(w));
    }
    return corners;
  }

  /// Decrease of sum (valence - 4)^2 over a, b, c, d when c is merged into a.
  int energy_decrease(halfedge_descriptor h0) const { return corners_from(h0).collapse_decrease(0); }


  /// The better rotation of an edge: its hexagon, k (1 or 2: the new edge joins corners
  /// k and k + 3) and the decrease of the valence energy (<= 0: none lowers it).
  struct Rotation
  {
    std::array<halfedge_descriptor, 6> hexagon;
    int k = 0;
    int energy_decrease = 0;
  };

  Rotation best_rotation(halfedge_descriptor h) const { return best_rotation(h, loss_of_old_ends(h)); }

  /// The same, given `loss_of_old_ends(h)`.
  Rotation best_rotation(halfedge_descriptor h, int loss) const
  {
    // A new end at its lowest valence or above gains at most 1 from its new edge, so
    // most edges (4-4 ones) cannot pay for a rotation: skip them before the hexagon.
    // (This passes over the rare inner vertex of valence 2, a doublet left in place.)
    Rotation best;
    if(loss + 2 <= 0 || !hexagon_around(h, best.hexagon))
      return best;
    for(int k : {1, 2}) {
      const int decrease = loss + gain_of_new_ends(best.hexagon, k);
      if(best.k == 0 || decrease > best.energy_decrease) {
        best.k = k;
        best.energy_decrease = decrease;
      }
    }
    return best;
  }

  /// The decrease of the valence energy of the ends of h's edge when it is rotated away.
  int loss_of_old_ends(halfedge_descriptor h) const
  {
    const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
    return Corners::edge_loss_decrease(valence(u), regular_valence(u)) +
           Corners::edge_loss_decrease(valence(v), regular_valence(v));
  }

  /// The change of the valence energy of hexagon corners k and k + 3 when they are joined.
  int gain_of_new_ends(const std::array<halfedge_descriptor, 6>& hexagon, int k) const
  {
    const vertex_descriptor p = source(hexagon[k], mesh_), q = source(hexagon[k + 3], mesh_);
    return -(Corners::edge_loss_decrease(valence(p) + 1, regular_valence(p)) +
             Corners::edge_loss_decrease(valence(q) + 1, regular_valence(q)));
  }

  /// Rotates the candidate's edge if that still lowers the energy (earlier operations
  /// of the pass may have changed the valences), keeps a valid manifold and folds no
  /// quad over (`rotation_keeps_faces_unfolded()`). Returns whether it did; counts the
  /// rotation or the refusal in `stats`.
  bool try_rotation(const Candidate& candidate, Collapse_statistics& stats)
  {
    const halfedge_descriptor h = candidate.edge;
    if(!still_in_quad(h, candidate.quad))
      return false;
    const Rotation rotation = best_rotation(h);
    if(rotation.energy_decrease <= 0)
      return false;
    if(!rotation_keeps_manifold(h, rotation.hexagon, rotation.k)) {
      ++stats.refused_topology;
      return false;
    }
    if(!rotation_keeps_faces_unfolded(rotation.hexagon, rotation.k)) {
      ++stats.refused_fold_over;
      return false;
    }
    rotate(h, rotation.hexagon, rotation.k);
    ++stats.rotated_edges;
    return true;
  }

  /// Collapses the quad along its better diagonal if that lowers the energy, keeps a
  /// valid manifold and folds no face over. Returns whether it did; counts the collapse
  /// or the refusal in `stats`.
  bool try_collapse(face_descriptor quad, Collapse_statistics& stats)
  {
    const halfedge_descriptor h0 = better_diagonal(quad);
    if(energy_decrease(h0) <= 0)
      return false;
    if(!keeps_manifold(h0)) {
      ++stats.refused_topology;
      return false;
    }
    const Vec3 merged = merged_position(h0);
    if(!keeps_faces_unfolded(h0, merged)) {
      ++stats.refused_fold_over;
      return false;
    }
    collapse(h0, merged);
    ++stats.collapsed_quads;
    return true;
  }

  /// The operations, each queueing the faces around the vertices it changed.
  void rotate(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon, int k)
  {
    const std::array<vertex_descriptor, 4> changed = {source(h, mesh_), target(h, mesh_), source(hexagon[k], mesh_),
                                                      source(hexagon[(k + 3) % 6], mesh_)};
    Operations::rotate(h, hexagon, k);
    for(vertex_descriptor w : changed)
      touch_faces_around(w);
  }

  void collapse(halfedge_descriptor h0, const Vec3& merged)
  {
    const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_);
    const std::array<vertex_descriptor, 3> changed = {source(h0, mesh_), target(h0, mesh_), target(h2, mesh_)};
    Operations::collapse(h0, merged);
    for(vertex_descriptor w : changed)
      touch_faces_around(w);
  }

  /// Once no operation lowers the energy by itself, what is left are mostly dipoles: a
  /// valence-3 vertex beside a valence-5 one. A rotation that keeps the energy moves a
  /// dipole by one step; it is kept only when a collapse or a rotation it makes
  /// possible (around its four vertices) then lowers the energy, else it is turned
  /// back. The energy drops at every kept pair, so the walk ends. Returns the number
  /// of rotations kept; counts them and the operations they made possible in `stats`
  /// (the refusals met on the way are the tries', not counted).
  std::size_t walk_dipoles(Collapse_statistics& stats)
  {
    Collapse_statistics tries;
    std::size_t kept = 0;
    const std::vector<face_descriptor> quads = quads_to_walk();
    Work_meter meter(*progress_, Remeshing_stage::COLLAPSE);
    std::size_t walked = 0;
    for(face_descriptor f : quads) {
      meter.add(1, [&] { return (double(pass_ - 1) + double(walked) / double(quads.size())) / double(maximum_passes_); });
      ++walked;
      // a collapse made possible by an earlier walk may have removed it; and around a
      // quad of regular corners, a rotation of one of its edges raises the energy
      if(!is_live_quad(f) || has_regular_corners(f))
        continue;
      for(halfedge_descriptor h : quad_edges_by_rank(f)) {
        if(!is_live_quad(f))
          break;
        std::array<halfedge_descriptor, 6> hexagon;
        if(!still_in_quad(h, f) || !hexagon_around(h, hexagon))
          continue;
        const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
        const int loss = loss_of_old_ends(h);
        for(int k : {1, 2}) {
          // The geometric check before the rotation (it reads only the hexagon's
          // corners): it refuses three tries in five, at half the cost of collecting
          // the candidates around (about 1,650 against 3,300 instructions a try on
          // refined_elephant, R^6), and a refused try then needs no rotation back.
          if(loss + gain_of_new_ends(hexagon, k) != 0 || !rotation_keeps_manifold(h, hexagon, k) ||
             !rotation_keeps_faces_unfolded(hexagon, k))
            continue;
          const vertex_descriptor p = source(hexagon[k], mesh_), q = source(hexagon[k + 3], mesh_);
          rotate_untracked(h, hexagon, k);
          if(do_first_allowed(candidates_around({u, v, p, q}), tries)) {
            for(vertex_descriptor w : {u, v, p, q})
              if(valence(w) > 0) // not merged away by the collapse
                touch_faces_around(w);
            ++kept;
            break;
          }
          // Back as it was: h runs from u to v again in its own face, so the faces keep
          // their places (the quad's other edges are still to try) and so does `hexagon`.
          // The hexagon around h now starts at p, where v is corner 6 - k.
          std::array<halfedge_descriptor, 6> back;
          hexagon_around(h, back);
          rotate_untracked(h, back, 6 - k);
        }
      }
    }
    stats.neutral_rotations += kept;
    stats.collapsed_quads += tries.collapsed_quads;
    stats.rotated_edges += tries.rotated_edges;
    return kept;
  }

  /// A rotation that queues no face: the walk's tries, which a rotation back may undo,
  /// change nothing the next passes need until one is kept.
  void rotate_untracked(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon, int k)
  {
    touching_ = false;
    rotate(h, hexagon, k);
    touching_ = true;
  }

  /// The quads the next walk tries: all of them the first time, then those that the
  /// operations since the last walk changed (the faces around the vertices they
  /// changed), by face index (deterministic). Adding their neighbours found 2 more kept
  /// rotations in 2,000 tries on refined_elephant R^6 (262 against 264 in all), for a
  /// third of the walk's time.
  std::vector<face_descriptor> quads_to_walk()
  {
    std::vector<face_descriptor> quads;
    ++walks_;
    if(walks_ == 1) {
      for(face_descriptor f : faces(mesh_))
        if(is_live_quad(f))
          quads.push_back(f);
    } else {
      for(face_descriptor g : changed_since_walk_) // listed once each (see touch_faces_around())
        if(is_live_quad(g))
          quads.push_back(g);
      std::sort(quads.begin(), quads.end(),
                [this](face_descriptor f, face_descriptor g) { return get(face_index_, f) < get(face_index_, g); });
    }
    changed_since_walk_.clear();
    return quads;
  }

  /// Whether the quad's four corners have their regular valence. Each of its edges
  /// u-v then rotates to join a corner p of the quad to a vertex q of the next quad:
  /// u, v and p add 3 to the energy, q takes away at most 1.
  bool has_regular_corners(face_descriptor f) const
  {
    for(vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, mesh_), mesh_))
      if(valence(w) != regular_valence(w))
        return false;
    return true;
  }

  /// The halfedges of a quad, from its first corner by `comes_before()` on.
  std::array<halfedge_descriptor, 4> quad_edges_by_rank(face_descriptor f) const
  {
    halfedge_descriptor first = halfedge(f, mesh_);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh_), mesh_))
      if(comes_before(source(h, mesh_), source(first, mesh_)))
        first = h;
    return {first, next(first, mesh_), next(next(first, mesh_), mesh_), prev(first, mesh_)};
  }

  /// Whether h is (still) a side of the quad: it may have been rotated into another
  /// face, or unlinked by a collapse (which leaves its face pointer as it was).
  bool still_in_quad(halfedge_descriptor h, face_descriptor quad) const
  {
    for(halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(quad, mesh_), mesh_))
      if(g == h)
        return true;
    return false;
  }

  /// The collapses and rotations that lower the energy in the quads around `around`,
  /// best first; ties go by where the quads are (`comes_before_quad()`), as the order
  /// of the faces around a vertex differs between mesh types.
  const std::vector<Candidate>& candidates_around(const std::array<vertex_descriptor, 4>& around)
  {
    std::vector<face_descriptor>& quads = nearby_quads_;
    quads.clear();
    ++nearby_stamp_;
    for(vertex_descriptor w : around)
      for(face_descriptor g : CGAL::faces_around_target(halfedge(w, mesh_), mesh_))
        if(g != GT::null_face() && is_live_quad(g) && nearby_in_stamp_[get(face_index_, g)] != nearby_stamp_) {
          nearby_in_stamp_[get(face_index_, g)] = nearby_stamp_;
          quads.push_back(g);
        }
    std::vector<Candidate>& candidates = nearby_candidates_;
    collect_candidates(quads, candidates);
    if(candidates.size() > 1)
      std::sort(candidates.begin(), candidates.end(), [this](const Candidate& x, const Candidate& y) {
        if(has_priority(x, y) || has_priority(y, x))
          return has_priority(x, y);
        if(x.quad != y.quad)
          return comes_before_quad(x.quad, y.quad);
        return x.rank_in_quad < y.rank_in_quad;
      });
    return candidates;
  }

  /// Quads in the order of their corners, each list sorted by `comes_before()`.
  bool comes_before_quad(face_descriptor f, face_descriptor g) const
  {
    auto sorted_corners = [this](face_descriptor quad) {
      std::array<vertex_descriptor, 4> corners;
      int i = 0;
      for(vertex_descriptor w : CGAL::vertices_around_face(halfedge(quad, mesh_), mesh_))
        corners[i++] = w;
      std::sort(corners.begin(), corners.end(),
                [this](vertex_descriptor x, vertex_descriptor y) { return comes_before(x, y); });
      return corners;
    };
    const std::array<vertex_descriptor, 4> x = sorted_corners(f), y = sorted_corners(g);
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end(),
                                        [this](vertex_descriptor a, vertex_descriptor b) { return comes_before(a, b); });
  }

  /// Does the first of the candidates that is allowed. Returns whether one was.
  bool do_first_allowed(const std::vector<Candidate>& candidates, Collapse_statistics& stats)
  {
    for(const Candidate& candidate : candidates)
      if(try_candidate(candidate, stats))
        return true;
    return false;
  }

  /// Does the candidate's collapse or rotation if it is still allowed (earlier
  /// operations may have removed or changed its quad). Returns whether it did.
  bool try_candidate(const Candidate& candidate, Collapse_statistics& stats)
  {
    if(!is_live_quad(candidate.quad))
      return false;
    return candidate.edge != null_halfedge() ? try_rotation(candidate, stats) : try_collapse(candidate.quad, stats);
  }

  bool rotate_edges_;
  std::vector<std::size_t> touched_in_pass_; // by face index: last pass that queued it
  // by face index: 1 + the number of walks before the face's last change was listed
  // (in changed_since_walk_)
  std::vector<std::size_t> changed_in_walk_;
  std::vector<face_descriptor> changed_since_walk_;
  std::size_t walks_ = 0;
  bool touching_ = true; // whether operations queue the faces they change
  const Progress* progress_ = &Progress::none(); // of the run
  int maximum_passes_ = 1;
  std::size_t pass_ = 0;
  std::vector<face_descriptor>* touched_ = nullptr; // the next pass's faces
  std::vector<face_descriptor> nearby_quads_;
  // by face index: the last `candidates_around()` that listed the face (no repeats)
  std::vector<std::size_t> nearby_in_stamp_;
  std::size_t nearby_stamp_ = 0;
  std::vector<Candidate> nearby_candidates_;
  std::vector<std::size_t> class_starts_; // group_by_priority_class()'s counts
  std::vector<Candidate> grouped_candidates_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H
