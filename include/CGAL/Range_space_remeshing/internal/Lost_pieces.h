// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOST_PIECES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOST_PIECES_H

// For the topology check (Topology_check.h): the connected components of the input
// with their Euler characteristics, those the output lacks (no intersection vertex
// on them), and the border cycles of the others that lie in one cell (no hyperplane
// crosses them). The components are labelled by a union-find over the face records
// in index order, not by a traversal of the mesh: neighbouring faces have close
// indices in most meshes, so the passes stay in cache.

#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Input>
class Lost_pieces
{
  using Levels = typename Input::Levels;
  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// What the Euler characteristic of a component is made of, and whether it has output.
  struct Counts
  {
    long vertices = 0, half_edges = 0, border_edges = 0, faces = 0;
    bool output = false;
  };

public:
  explicit Lost_pieces(Input& input)
    : input_(input), number_of_faces_(std::uint32_t(input.number_of_input_faces()))
  {}

  /// Labels the input components, marks those on which no vertex of `vertices` lies
  /// as lost, and returns the Euler characteristic of the others (the input's is kept).
  template <class Vertices>
  long label_components(const Vertices& vertices)
  {
    std::vector<Counts> counts = count_per_component(parents_of_faces());
    for(const auto& v : vertices)
      counts[component_[v.face_id]].output = true;
    long chi_kept = 0;
    lost_component_.assign(counts.size(), 0);
    for(std::uint32_t c = 0; c < counts.size(); ++c) {
      const Counts& k = counts[c];
      const long chi = k.vertices - (k.half_edges + k.border_edges) / 2 + k.faces;
      input_euler_characteristic_ += chi;
      if(k.output)
        chi_kept += chi;
      else
        lost_component_[c] = 1;
    }
    return chi_kept;
  }

  std::size_t number_of_components() const { return lost_component_.size(); }
  long input_euler_characteristic() const { return input_euler_characteristic_; }
  std::uint32_t component_of(std::uint32_t f) const { return component_[f]; }
  bool is_lost_component(std::uint32_t c) const { return lost_component_[c]; }
  bool is_lost(std::uint32_t f) const { return lost_component_[component_[f]]; }

  /// Calls `visit(f, e, faces)` for each border cycle whose vertices all lie in one
  /// cell, in components that have an output: (f, e) its first border edge in face
  /// order, `faces` the faces of its border edges in order along it.
  template <class Visit>
  void for_each_border_cycle_in_one_cell(const Visit& visit) const
  {
    std::vector<std::uint8_t> walked(3 * std::size_t(number_of_faces_), 0);
    std::vector<std::uint32_t> faces;
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      for(int e = 0; e < 3; ++e) {
        if(input_.neighbours_of(f)[e] != Input::border || walked[3 * f + e] || is_lost(f))
          continue;
        if(walk_border_cycle(f, e, walked, faces))
          visit(f, e, faces);
      }
  }

private:
  /// The union-find forest of the faces across their edges.
  std::vector<std::uint32_t> parents_of_faces() const
  {
    std::vector<std::uint32_t> parent(number_of_faces_);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      parent[f] = f;
      for(std::uint32_t n : input_.neighbours_of(f))
        if(n != Input::border && n < f)
          unite(parent, f, n);
    }
    return parent;
  }

  static void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
  {
    a = union_find_root(parent, a);
    b = union_find_root(parent, b);
    if(a != b)
      parent[(std::max)(a, b)] = (std::min)(a, b);
  }

  /// Numbers the components in the order of their first faces, in `component_`, and
  /// counts their vertices, half-edges, border edges and faces.
  std::vector<Counts> count_per_component(std::vector<std::uint32_t> parent)
  {
    std::vector<Counts> counts;
    component_.assign(number_of_faces_, none);
    std::vector<std::uint32_t> vertex_owner(input_.number_of_input_vertices(), 0); // 1 + component
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      std::uint32_t& c = component_[union_find_root(parent, f)];
      if(c == none) {
        c = std::uint32_t(counts.size());
        counts.emplace_back();
      }
      component_[f] = c;
      Counts& k = counts[c];
      ++k.faces;
      k.half_edges += 3;
      for(int e = 0; e < 3; ++e) {
        const std::uint32_t v = input_.corners_of(f)[e];
        if(vertex_owner[v] != c + 1) {
          vertex_owner[v] = c + 1;
          ++k.vertices;
        }
        k.border_edges += input_.neighbours_of(f)[e] == Input::border ? 1 : 0;
      }
    }
    return counts;
  }

  /// Walks the border cycle of edge e of face f, marking its edges in `walked` and
  /// listing their faces in `faces`; whether all its vertices lie in one cell.
  bool walk_border_cycle(std::uint32_t f, int e, std::vector<std::uint8_t>& walked,
                         std::vector<std::uint32_t>& faces) const
  {
    const Levels& ceiling = input_.ceiling_of(input_.corners_of(f)[e]);
    bool one_cell = true;
    faces.clear();
    std::uint32_t g = f;
    int edge = e;
    do {
      walked[3 * g + edge] = 1;
      faces.push_back(g);
      one_cell = one_cell && same_levels(input_.ceiling_of(input_.corners_of(g)[edge]), ceiling);
      next_border_edge(g, edge);
    } while(g != f || edge != e);
    return one_cell;
  }

  /// The border edge that follows edge `e` of face `f` along the border, turning
  /// around the vertex that ends it.
  void next_border_edge(std::uint32_t& f, int& e) const
  {
    const std::uint32_t pivot = input_.corners_of(f)[(e + 1) % 3];
    for(std::uint32_t steps = 0; steps <= number_of_faces_; ++steps) {
      e = (e + 1) % 3; // the face's edge leaving the pivot
      const std::uint32_t n = input_.neighbours_of(f)[e];
      if(n == Input::border)
        return;
      f = n;
      const auto& corners = input_.corners_of(f);
      e = int(std::find(corners.begin(), corners.end(), pivot) - corners.begin());
      e = (e + 2) % 3; // the edge entering the pivot, shared with the previous face
    }
    CGAL_error_msg("Range_space_remeshing: endless border");
  }

  Input& input_;
  std::uint32_t number_of_faces_;
  std::vector<std::uint32_t> component_;     // by face id
  std::vector<std::uint8_t> lost_component_; // by component
  long input_euler_characteristic_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOST_PIECES_H
