// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H

// The quad collapse of section 6 of the paper, on any MutableFaceGraph. A quad
// (a, b, c, d) with halfedges h0 = a->b, h1 = b->c, h2 = c->d, h3 = d->a is collapsed
// along (a, c) by merging c into a: h0 takes the place of opposite(h1) and h3 the
// place of opposite(h2), so edges a-b, b-c become one and so do c-d, d-a; the quad,
// the edges of h1 and h2, and c are removed. Only pointers are rewired: no new
// element, so descriptors and indices of the survivors stay valid.
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
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

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
{
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

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
    : rotate_edges_(rotate_edges), mesh_(mesh), vpm_(vpm), planes_(planes), constrained_(constrained),
      vertex_index_(vertex_index), normals_(normals), face_index_(face_index),
      removed_faces_(index_bound(faces(mesh), face_index), 0), is_quad_(removed_faces_.size(), 0),
      touched_in_pass_(removed_faces_.size(), 0), changed_in_walk_(removed_faces_.size(), 0),
      valences_(index_bound(vertices(mesh), vertex_index)),
      on_border_(valences_.size(), 0), nearby_in_stamp_(removed_faces_.size(), 0)
  {
    for(face_descriptor f : faces(mesh_))
      is_quad_[get(face_index_, f)] = degree(f, mesh_) == 4;
    for(vertex_descriptor v : vertices(mesh_)) {
      valences_[index(v)] = int(degree(v, mesh_));
      on_border_[index(v)] = bool(is_border(v, mesh_));
      // a border vertex keeps its border halfedge, which no collapse removes (see
      // set_inner_halfedge()); meshes from elsewhere need not point there yet
      if(on_border_[index(v)])
        set_halfedge(v, *is_border(v, mesh_), mesh_);
    }
  }

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
    progress_->report(Remeshing_stage::COLLAPSE, 1);
    remove_unlinked_elements();
    return stats;
  }

private:
  std::size_t index(vertex_descriptor v) const { return get(vertex_index_, v); }
  int valence(vertex_descriptor v) const { return valences_[index(v)]; }
  // Border vertices are never moved nor merged; a regular one has valence 3 (two border
  // edges and one inside), and may go down to 2 (a corner of the surface).
  bool on_border(vertex_descriptor v) const { return on_border_[index(v)]; }
  int regular_valence(vertex_descriptor v) const { return on_border(v) ? 3 : 4; }
  int lowest_valence(vertex_descriptor v) const { return on_border(v) ? 2 : 3; }
  /// Sets the halfedge of v, unless v is on the border: its halfedge stays the border one.
  void set_inner_halfedge(vertex_descriptor v, halfedge_descriptor h)
  {
    if(!on_border(v))
      set_halfedge(v, h, mesh_);
  }
  Vec3 position(vertex_descriptor v) const { return to_vec3(get(vpm_, v)); }
  static halfedge_descriptor null_halfedge() { return GT::null_halfedge(); }

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
  /// in linear time. (A comparison sort compared candidates about a million times in
  /// the first pass: 1.2 % of the pipeline's instructions on refined_elephant, R^6.)
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

  /// The six halfedges around the two quads of the edge of h (u -> v), from v on:
  /// hexagon[i] goes from corner i to corner i + 1, corner 0 is v and corner 3 is u.
  /// False where the edge is not between two distinct quads.
  bool hexagon_around(halfedge_descriptor h, std::array<halfedge_descriptor, 6>& hexagon) const
  {
    const halfedge_descriptor o = opposite(h, mesh_);
    if(is_border(h, mesh_) || is_border(o, mesh_) || face(h, mesh_) == face(o, mesh_) ||
       !is_quad(face(h, mesh_)) || !is_quad(face(o, mesh_)))
      return false;
    hexagon[0] = next(h, mesh_);
    hexagon[3] = next(o, mesh_);
    for(int i : {1, 2, 4, 5})
      hexagon[i] = next(hexagon[i - 1], mesh_);
    return true;
  }

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

  // No operation changes the degree of a face it keeps (see is_quad_).
  bool is_quad(face_descriptor f) const { return is_quad_[get(face_index_, f)]; }
  bool is_live_quad(face_descriptor f) const { return !removed_faces_[get(face_index_, f)] && is_quad(f); }

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
    const Vec3 position = merged_position(h0);
    if(!keeps_faces_unfolded(h0, position)) {
      ++stats.refused_fold_over;
      return false;
    }
    collapse(h0, position);
    ++stats.collapsed_quads;
    return true;
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

  /// The hexagon's corners are six distinct vertices, the new edge's ends are not
  /// joined yet, u and v keep their lowest valence, and neither is constrained (its
  /// edges may be a feature the caller keeps).
  bool rotation_keeps_manifold(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon,
                               int k) const
  {
    const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
    if(get(constrained_, u) || get(constrained_, v) || valence(u) <= lowest_valence(u) ||
       valence(v) <= lowest_valence(v))
      return false;
    std::array<vertex_descriptor, 6> corners;
    for(int i = 0; i < 6; ++i)
      corners[i] = source(hexagon[i], mesh_);
    for(int i = 0; i < 6; ++i)
      for(int j = i + 1; j < 6; ++j)
        if(corners[i] == corners[j])
          return false;
    const vertex_descriptor p = corners[k], q = corners[k + 3];
    for(vertex_descriptor w : CGAL::vertices_around_target(halfedge(p, mesh_), mesh_))
      if(w == q)
        return false;
    return true;
  }

  /// Both new quads face like the two old ones together, and, as in a collapse, stay
  /// convex where both old ones were (else each fan from the new edge turns like its quad).
  bool rotation_keeps_faces_unfolded(const std::array<halfedge_descriptor, 6>& hexagon, int k) const
  {
    corners_.clear();
    for(int i = 0; i < 6; ++i)
      corners_.push_back(position(source(hexagon[i], mesh_)));
    const Vec3 normal_before = newell_normal(corners_); // the hexagon's: both old quads'
    std::vector<Vec3>& quad = quad_corners_;
    auto quad_from = [&](int first) -> const std::vector<Vec3>& {
      quad.clear();
      for(int i = 0; i < 4; ++i)
        quad.push_back(corners_[(first + i) % 6]);
      return quad;
    };
    const bool were_convex = is_convex(quad_from(0), newell_normal(quad_from(0))) &&
                             is_convex(quad_from(3), newell_normal(quad_from(3)));
    return turns_like_before(quad_from(k), normal_before, were_convex) &&
           turns_like_before(quad_from(k + 3), normal_before, were_convex);
  }

  /// The rule of both operations for a changed face: its normal keeps the direction of
  /// `normal_before`, and it stays convex if it was, else every triangle of its fan from
  /// the first corner turns like it.
  static bool turns_like_before(const std::vector<Vec3>& polygon, const Vec3& normal_before, bool was_convex)
  {
    const Vec3 normal = newell_normal(polygon);
    return dot(normal, normal_before) > 0 &&
           (was_convex ? is_convex(polygon, normal) : fan_turns_with(polygon, normal));
  }

  /// Turns the edge of h (u -> v) to join hexagon corners k and k + 3 (mod 6): h's face
  /// becomes corners k .. k + 3, the opposite face corners k + 3 .. k + 6. (k = 4 or 5
  /// gives the diagonal of k = 1 or 2 with the two faces the other way round.)
  void rotate(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon, int k)
  {
    const halfedge_descriptor o = opposite(h, mesh_);
    const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
    const vertex_descriptor p = source(hexagon[k], mesh_), q = source(hexagon[(k + 3) % 6], mesh_);
    auto link = [this](halfedge_descriptor diagonal, const halfedge_descriptor* sides) {
      const face_descriptor f = face(diagonal, mesh_);
      set_next(diagonal, sides[0], mesh_);
      set_next(sides[0], sides[1], mesh_);
      set_next(sides[1], sides[2], mesh_);
      set_next(sides[2], diagonal, mesh_);
      for(int i = 0; i < 3; ++i)
        set_face(sides[i], f, mesh_);
      set_halfedge(f, diagonal, mesh_);
    };
    const std::array<halfedge_descriptor, 6> from_k = {hexagon[k], hexagon[(k + 1) % 6], hexagon[(k + 2) % 6],
                                                       hexagon[(k + 3) % 6], hexagon[(k + 4) % 6],
                                                       hexagon[(k + 5) % 6]};
    if(halfedge(u, mesh_) == o)
      set_inner_halfedge(u, hexagon[2]); // hexagon[2] ends at corner 3, u
    if(halfedge(v, mesh_) == h)
      set_inner_halfedge(v, hexagon[5]); // hexagon[5] ends at corner 0, v
    set_target(h, p, mesh_);
    set_target(o, q, mesh_);
    link(h, &from_k[0]);
    link(o, &from_k[3]);
    --valences_[index(u)];
    --valences_[index(v)];
    ++valences_[index(p)];
    ++valences_[index(q)];
    for(vertex_descriptor w : {u, v, p, q})
      touch_faces_around(w);
  }

  /// Link condition for quads: the merged vertex has one disk of faces, no two edges
  /// join the same vertices, no face visits a vertex twice, b and d keep valence 3.
  bool keeps_manifold(halfedge_descriptor h0) const
  {
    const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_);
    const vertex_descriptor a = source(h0, mesh_), b = target(h0, mesh_), c = target(h1, mesh_),
                            d = target(h2, mesh_);
    if(a == c || b == d || get(constrained_, a) || get(constrained_, c) || on_border(a) || on_border(c))
      return false;
    if(valence(b) <= lowest_valence(b) || valence(d) <= lowest_valence(d) || valence(a) < 3 || valence(c) < 3)
      return false;
    auto& around_a = around_a_;
    around_a.clear();
    for(vertex_descriptor w : CGAL::vertices_around_target(opposite(h0, mesh_), mesh_))
      around_a.push_back(w);
    for(vertex_descriptor w : CGAL::vertices_around_target(h1, mesh_))
      if(w != b && w != d && std::find(around_a.begin(), around_a.end(), w) != around_a.end())
        return false;
    if(std::find(around_a.begin(), around_a.end(), c) != around_a.end())
      return false;
    const face_descriptor quad = face(h0, mesh_);
    auto& faces_a = faces_a_;
    faces_a.clear();
    for(face_descriptor g : CGAL::faces_around_target(opposite(h0, mesh_), mesh_))
      if(g != quad)
        faces_a.push_back(g);
    for(face_descriptor g : CGAL::faces_around_target(h1, mesh_))
      if(g != quad && std::find(faces_a.begin(), faces_a.end(), g) != faces_a.end())
        return false;
    return true;
  }

  /// The paper's placement, generalised as in the relaxation: the midpoint of a and c
  /// moved to the nearest minimiser of the distances to the union of their tangent
  /// planes (along the normal in a smooth region, onto the line of a crease); on opened
  /// creases, `merged_on_creases()`.
  Vec3 merged_position(halfedge_descriptor h0) const
  {
    const vertex_descriptor a = source(h0, mesh_), c = target(next(h0, mesh_), mesh_);
    const Vec3 pa = position(a), pc = position(c);
    Vec3 mid = {{(pa[0] + pc[0]) / 2, (pa[1] + pc[1]) / 2, (pa[2] + pc[2]) / 2}};
    if(merged_on_creases(get(planes_, a), pa, get(planes_, c), pc, mid, corners_, quad_corners_))
      return mid;
    Quadric quadric;
    quadric.add_planes(get(planes_, a));
    quadric.add_planes(get(planes_, c));
    return Quadric_projection(quadric, quadric_truncation)(mid);
  }

  Vec3 merged_normal(vertex_descriptor a, vertex_descriptor c) const
  {
    const Vec3& na = normals_[index(a)];
    const Vec3& nc = normals_[index(c)];
    return normalized(Vec3{{na[0] + nc[0], na[1] + nc[1], na[2] + nc[2]}});
  }

  /// Whether every face around a and c (but the quad) stays unfolded once a and c are
  /// one vertex at `merged`: its normal keeps its direction, a convex face stays
  /// convex, and every triangle of the fan from the merged vertex turns like the face.
  bool keeps_faces_unfolded(halfedge_descriptor h0, const Vec3& merged) const
  {
    const face_descriptor quad = face(h0, mesh_);
    for(halfedge_descriptor around : {opposite(h0, mesh_), next(h0, mesh_)}) // targets a, c
      for(halfedge_descriptor h : CGAL::halfedges_around_target(around, mesh_)) {
        if(is_border(h, mesh_) || face(h, mesh_) == quad)
          continue;
        corners_.clear();
        halfedge_descriptor g = h; // corners from the merged vertex on
        do {
          corners_.push_back(position(target(g, mesh_)));
          g = next(g, mesh_);
        } while(g != h);
        const Vec3 normal_before = newell_normal(corners_);
        const bool was_convex = is_convex(corners_, normal_before);
        corners_.front() = merged;
        if(!turns_like_before(corners_, normal_before, was_convex))
          return false;
      }
    return true;
  }

  void collapse(halfedge_descriptor h0, const Vec3& merged)
  {
    const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_), h3 = next(h2, mesh_);
    const halfedge_descriptor o1 = opposite(h1, mesh_), o2 = opposite(h2, mesh_);
    const vertex_descriptor a = source(h0, mesh_), b = target(h0, mesh_), c = target(h1, mesh_),
                            d = target(h2, mesh_);
    const Vec3 normal = merged_normal(a, c);

    std::vector<halfedge_descriptor>& into_c = into_c_;
    into_c.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_target(h1, mesh_))
      if(h != h1 && h != o2)
        into_c.push_back(h);
    for(halfedge_descriptor h : into_c)
      set_target(h, a, mesh_);
    valences_[index(a)] += valences_[index(c)] - 2;
    valences_[index(c)] = 0; // merged away
    --valences_[index(b)];
    --valences_[index(d)];

    replace_in_face(o1, h0);
    replace_in_face(o2, h3);
    set_halfedge(a, opposite(h0, mesh_), mesh_);
    set_inner_halfedge(b, h0);
    set_inner_halfedge(d, opposite(h3, mesh_));

    append_planes(a, c);
    put(vpm_, a, Point(merged[0], merged[1], merged[2]));
    normals_[index(a)] = normal;

    const face_descriptor quad = face(h1, mesh_);
    removed_faces_[get(face_index_, quad)] = true;
    unlinked_.push_back({quad, h1, h2, c});
    for(vertex_descriptor v : {a, b, d})
      touch_faces_around(v);
  }

  /// Dissolves the vertices of valence 2 (doublets: two quads sharing two edges, as
  /// the dual leaves where it joins faces) whose two faces are distinct quads: the two
  /// become one quad. Refused where a neighbour would drop below valence 3, where the
  /// merged face would visit a vertex twice, or where it would fold over.
  std::size_t remove_doublets()
  {
    std::vector<vertex_descriptor> doublets;
    for(vertex_descriptor v : vertices(mesh_))
      if(valence(v) == 2 && !on_border(v))
        doublets.push_back(v);
    std::size_t removed = 0;
    for(vertex_descriptor v : doublets) {
      const halfedge_descriptor o2 = halfedge(v, mesh_);        // b -> v, in F
      const halfedge_descriptor e1 = next(o2, mesh_);           // v -> a, in F
      const halfedge_descriptor o1 = opposite(e1, mesh_);       // a -> v, in G
      const halfedge_descriptor e2 = next(o1, mesh_);           // v -> b, in G
      if(e2 != opposite(o2, mesh_) || is_border(o2, mesh_) || is_border(o1, mesh_))
        continue;
      const face_descriptor f = face(o2, mesh_), g = face(o1, mesh_);
      if(f == g || !is_quad(f) || !is_quad(g))
        continue;
      const vertex_descriptor a = target(e1, mesh_), b = target(e2, mesh_);
      const halfedge_descriptor a_x = next(e1, mesh_), x_b = prev(o2, mesh_);
      const halfedge_descriptor b_y = next(e2, mesh_), y_a = prev(o1, mesh_);
      if(a == b || target(a_x, mesh_) == target(b_y, mesh_) || valence(a) <= lowest_valence(a) ||
         valence(b) <= lowest_valence(b) || get(constrained_, v))
        continue;
      // the merged quad (a, x, b, y) must turn like the two it replaces
      corners_ = {position(a), position(target(a_x, mesh_)), position(b), position(target(b_y, mesh_))};
      const Vec3 merged = newell_normal(corners_);
      corners_ = {position(v), position(a), position(target(a_x, mesh_)), position(b)};
      Vec3 before = newell_normal(corners_);
      corners_ = {position(v), position(b), position(target(b_y, mesh_)), position(a)};
      const Vec3 other = newell_normal(corners_);
      for(int d = 0; d < 3; ++d)
        before[d] += other[d];
      if(!(dot(merged, before) > 0))
        continue;
      set_next(x_b, b_y, mesh_);
      set_next(y_a, a_x, mesh_);
      set_face(b_y, f, mesh_);
      set_face(y_a, f, mesh_);
      set_halfedge(f, a_x, mesh_);
      set_inner_halfedge(a, y_a);
      set_inner_halfedge(b, x_b);
      --valences_[index(a)];
      --valences_[index(b)];
      valences_[index(v)] = 0;
      removed_faces_[get(face_index_, g)] = true;
      unlinked_.push_back({g, e1, e2, v});
      ++removed;
    }
    return removed;
  }

  /// Removes the elements of the collapsed quads. Deferred to the end of the run: a
  /// `Polyhedron_3` frees removed faces, and the pass lists may still name them.
  void remove_unlinked_elements()
  {
    for(const Unlinked& u : unlinked_) {
      remove_face(u.quad, mesh_);
      remove_edge(edge(u.h1, mesh_), mesh_);
      remove_edge(edge(u.h2, mesh_), mesh_);
      remove_vertex(u.c, mesh_);
    }
    unlinked_.clear();
  }

  /// The tangent planes of `to` become those of both: in place where the map gives
  /// references (no copy of the list), through get and put otherwise.
  void append_planes(vertex_descriptor to, vertex_descriptor from)
  {
    using Reference = typename boost::property_traits<TangentPlanesMap>::reference;
    if constexpr(std::is_lvalue_reference<Reference>::value &&
                 !std::is_const<std::remove_reference_t<Reference>>::value) {
      auto& merged = get(planes_, to);
      const auto& added = get(planes_, from);
      merged.insert(merged.end(), added.begin(), added.end());
    } else {
      auto merged = get(planes_, to);
      const auto added = get(planes_, from);
      merged.insert(merged.end(), added.begin(), added.end());
      put(planes_, to, merged);
    }
  }

  /// `replacement` takes the place of `h` in h's face.
  void replace_in_face(halfedge_descriptor h, halfedge_descriptor replacement)
  {
    const face_descriptor f = face(h, mesh_);
    set_next(prev(h, mesh_), replacement, mesh_);
    set_next(replacement, next(h, mesh_), mesh_);
    set_face(replacement, f, mesh_);
    if(halfedge(f, mesh_) == h)
      set_halfedge(f, replacement, mesh_);
  }

  bool rotate_edges_;
  PolygonMesh& mesh_;
  VertexPointMap vpm_;
  TangentPlanesMap planes_;
  ConstrainedMap constrained_;
  VertexIndexMap vertex_index_;
  std::vector<Vec3>& normals_;
  FaceIndexMap face_index_;
  // by face index: faces are never created. (Bytes, not bits: read for every quad examined.)
  std::vector<std::uint8_t> removed_faces_;
  // by face index, the degree test cached: a collapse replaces a corner of the faces
  // around it, a rotation or a doublet removal makes quads of quads
  std::vector<std::uint8_t> is_quad_;
  std::vector<std::size_t> touched_in_pass_; // by face index: last pass that queued it
  // by face index: 1 + the number of walks before the face's last change was listed
  // (in changed_since_walk_)
  std::vector<std::size_t> changed_in_walk_;
  std::vector<face_descriptor> changed_since_walk_;
  std::size_t walks_ = 0;
  bool touching_ = true; // whether operations queue the faces they change
  std::vector<int> valences_;                // by vertex index
  std::vector<std::uint8_t> on_border_;      // by vertex index
  const Progress* progress_ = &Progress::none(); // of the run
  int maximum_passes_ = 1;
  std::size_t pass_ = 0;
  std::vector<face_descriptor>* touched_ = nullptr; // the next pass's faces
  mutable std::vector<vertex_descriptor> around_a_;
  mutable std::vector<face_descriptor> faces_a_;
  std::vector<halfedge_descriptor> into_c_;
  std::vector<face_descriptor> nearby_quads_;
  // by face index: the last `candidates_around()` that listed the face (no repeats)
  std::vector<std::size_t> nearby_in_stamp_;
  std::size_t nearby_stamp_ = 0;
  std::vector<Candidate> nearby_candidates_;
  std::vector<std::size_t> class_starts_; // group_by_priority_class()'s counts
  std::vector<Candidate> grouped_candidates_;
  struct Unlinked // what a collapse (or a doublet removal) took out of the connectivity
  {
    face_descriptor quad;
    halfedge_descriptor h1, h2; // one halfedge of each of the two removed edges
    vertex_descriptor c;
  };
  std::vector<Unlinked> unlinked_;
  mutable std::vector<Vec3> corners_;
  mutable std::vector<Vec3> quad_corners_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COLLAPSER_H
