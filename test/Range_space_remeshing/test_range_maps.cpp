// The ready-made range maps: Gauss map and position + normal. Every face in one cell
// (bounded variation), and the paper's anisotropy claim: under the Gauss map, faces
// are elongated along the direction of minimum curvature with an aspect ratio that
// follows the ratio of the principal curvatures; under position + normal, the normal
// weight moves the remesh from anisotropic to uniform.
#include "test_support.h"

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/Sized_range_map.h>
#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <numeric>
#include <limits>

using namespace test;
namespace params = CGAL::parameters;

/// A closed capsule along z: a cylinder of radius r and length `length` between two
/// hemispheres, from rings of `around` vertices.
Mesh make_capsule(double r, double length, int around, int rings_per_cap, int rings_along)
{
  std::vector<std::pair<double, double>> profile; // (radius, z), bottom to top, no poles
  for(int i = 1; i <= rings_per_cap; ++i) {
    const double phi = -M_PI / 2 + M_PI / 2 * i / rings_per_cap;
    profile.emplace_back(r * std::cos(phi), r * std::sin(phi));
  }
  for(int i = 1; i <= rings_along; ++i)
    profile.emplace_back(r, length * i / rings_along);
  for(int i = 1; i < rings_per_cap; ++i) {
    const double phi = M_PI / 2 * i / rings_per_cap;
    profile.emplace_back(r * std::cos(phi), length + r * std::sin(phi));
  }
  Mesh m;
  const auto bottom = m.add_vertex(Point(0, 0, -r));
  std::vector<std::vector<Mesh::Vertex_index>> rings;
  for(const auto& [radius, z] : profile) {
    rings.emplace_back();
    for(int j = 0; j < around; ++j) {
      const double t = 2 * M_PI * j / around;
      rings.back().push_back(m.add_vertex(Point(radius * std::cos(t), radius * std::sin(t), z)));
    }
  }
  const auto top = m.add_vertex(Point(0, 0, length + r));
  for(int j = 0; j < around; ++j) {
    const int k = (j + 1) % around;
    m.add_face(bottom, rings.front()[k], rings.front()[j]);
    m.add_face(top, rings.back()[j], rings.back()[k]);
    for(std::size_t i = 0; i + 1 < rings.size(); ++i) {
      m.add_face(rings[i][j], rings[i][k], rings[i + 1][k]);
      m.add_face(rings[i][j], rings[i + 1][k], rings[i + 1][j]);
    }
  }
  return m;
}

/// Median over the faces whose vertices all satisfy `near` of (extent along axis
/// `along`) / (extent along axis `across`); also returns how many faces counted.
template <class Near>
std::pair<double, std::size_t> median_aspect(const Mesh& remesh, int along, int across, Near near)
{
  std::vector<double> ratios;
  for(auto f : faces(remesh)) {
    bool inside = true;
    for(auto v : CGAL::vertices_around_face(halfedge(f, remesh), remesh))
      inside = inside && near(remesh.point(v));
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::face_bbox(f, remesh);
    if(inside && box.max(across) > box.min(across))
      ratios.push_back((box.max(along) - box.min(along)) / (box.max(across) - box.min(across)));
  }
  if(ratios.empty())
    return {0, 0};
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  return {ratios[ratios.size() / 2], ratios.size()};
}

/// The Gauss map on an ellipsoid of semi-axes (3, 2, 1): at the end of each axis the
/// principal curvatures are known, their ratio is 9/4, 9 or 4, and the faces there must
/// be elongated along the flatter direction by that ratio. Near the end of an axis,
/// the Gauss map pushed onto the cube is the gradient of the height function, linear
/// to first order: cells become rectangles of sides h / kappa_1 and h / kappa_2.
void test_gauss_map_anisotropy()
{
  const double semi[3] = {3, 2, 1};
  const Mesh ellipsoid = make_ellipsoid(semi[0], semi[1], semi[2], 6);
  Mesh remesh;
  const auto f = RSR::make_gauss_range_map(ellipsoid);
  const double h = 0.04; // not 1/n: the sides of the cube are not grid planes
  remesh_and_check(ellipsoid, remesh, RSR::parameters::range_map(f).grid_spacing(h));
  std::cout << "Gauss map of the ellipsoid: " << num_vertices(remesh) << " vertices" << std::endl;
  for(int axis = 0; axis < 3; ++axis) {
    // the two other axes: curvature at the end of `axis` along axis i is semi[axis] / semi[i]^2
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const int flat = semi[i] > semi[j] ? i : j, bent = flat == i ? j : i;
    const double expected = (semi[flat] * semi[flat]) / (semi[bent] * semi[bent]);
    // faces near the end of the axis, within 3 expected face sizes h / kappa of it
    auto near = [&](const Point& p) {
      const double size_flat = h * semi[flat] * semi[flat] / semi[axis];
      const double size_bent = h * semi[bent] * semi[bent] / semi[axis];
      return p[axis] > 0 && std::abs(p[flat]) < 3 * size_flat && std::abs(p[bent]) < 3 * size_bent;
    };
    const auto [aspect, counted] = median_aspect(remesh, flat, bent, near);
    std::cout << "  end of axis " << axis << ": median aspect " << aspect << " over " << counted
              << " faces, curvature ratio " << expected << std::endl;
    CHECK(counted >= 8);
    // measured within 4 % (h = 0.03 to 0.06): the curvatures vary over three faces;
    // 10 % leaves room for where whole faces fall in the window
    CHECK(std::abs(aspect / expected - 1) < 0.1);
  }
}

/// Position + normal on a capsule: along the cylinder the normal does not change, so
/// with a large normal weight faces are long along the axis (bounded by the position
/// part) and narrow around it (bounded by the normal part); with a normal weight near
/// 0 they are as long as wide.
void test_position_normal_weights()
{
  const double radius = 1, length = 8;
  const Mesh capsule = make_capsule(radius, length, 256, 32, 320);
  auto on_cylinder = [&](const Point& p) { return p.z() > 1 && p.z() < length - 1 && p.x() > 0.3; };
  // extent along the axis over extent along y, on the side x > 0 (where the circle
  // runs along y)
  auto near = [&](const Point& p) { return on_cylinder(p) && std::abs(p.y()) < 0.3; };
  const double h = 0.2;
  double previous = 0;
  for(double normal_weight : {1e-3, 2.0, 5.0}) {
    Mesh remesh;
    const auto f = RSR::make_position_normal_range_map(capsule, 1.0, normal_weight);
    remesh_and_check(capsule, remesh, RSR::parameters::range_map(f).grid_spacing(h));
    const auto [aspect, counted] = median_aspect(remesh, 2, 1, near);
    std::cout << "position + normal, normal weight " << normal_weight << ": " << num_vertices(remesh)
              << " vertices, median aspect " << aspect << " over " << counted << " faces" << std::endl;
    CHECK(counted >= 8);
    if(normal_weight < 0.01)
      CHECK(std::abs(aspect - 1) < 0.2); // uniform: the cells of the identity map
    else
      CHECK(aspect > 1.5 * previous); // more normal weight, longer faces
    previous = aspect;
  }
}

/// Largest extent of a face of `remesh` along a coordinate axis, in cells of size h.
double largest_extent(const Mesh& remesh, double h)
{
  double worst = 0;
  for(auto face : faces(remesh)) {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::face_bbox(face, remesh);
    for(int d = 0; d < 3; ++d)
      worst = std::max(worst, (box.max(d) - box.min(d)) / h);
  }
  return worst;
}

/// Bounded variation: the positions of every face's vertices (sampled on the input)
/// differ by at most h / position_weight per coordinate, whatever the normal weight;
/// also where the input lies in grid planes, its vertices on grid edges (a lattice
/// cube: every intersection vertex has a degenerate projection).
void test_bounded_position_variation()
{
  for(double h : {1.0, 0.5}) {
    const Mesh cube = make_lattice_cube(3);
    Mesh remesh;
    remesh_and_check(cube, remesh, params::grid_spacing(h));
    const double worst = largest_extent(remesh, h);
    std::cout << "lattice cube, h = " << h << ": largest face extent " << worst << " cells" << std::endl;
    CHECK(worst <= 1 + 1e-9);
  }
  const Mesh input = make_ellipsoid(1.5, 1.0, 0.7, 4);
  for(double normal_weight : {0.5, 2.0}) {
    const double position_weight = 2.0, h = 0.1;
    Mesh remesh;
    const auto f = RSR::make_position_normal_range_map(input, position_weight, normal_weight);
    remesh_and_check(input, remesh, RSR::parameters::range_map(f).grid_spacing(h));
    const double worst = largest_extent(remesh, h / position_weight);
    std::cout << "R^6, normal weight " << normal_weight << ": largest position extent " << worst
              << " cells" << std::endl;
    CHECK(worst <= 1 + 1e-9);
  }
}

/// The colour-gradient magnitudes of a colour linear in z on the unit sphere,
/// r = (z + 1) / 2: on the surface its gradient has length sin(theta) / 2, 0.5 at the
/// equator; the constant channels have none.
void test_color_gradient_magnitudes()
{
  Mesh sphere = make_sphere(1.0, 5);
  auto colors = sphere.add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:rgb").first;
  for(auto v : vertices(sphere))
    colors[v] = {{(sphere.point(v).z() + 1) / 2, 0.25, 1.0}};
  const RSR::Color_gradient_magnitude_map<Mesh, decltype(colors)> gradients(sphere, colors);
  double worst = 0;
  std::size_t counted = 0;
  for(auto v : vertices(sphere))
    if(std::abs(sphere.point(v).z()) < 0.05) {
      const auto g = get(gradients, v);
      worst = std::max(worst, std::max(std::abs(g[0] - 0.5), std::max(std::abs(g[1]), std::abs(g[2]))));
      ++counted;
    }
  std::cout << "colour gradient on the equator of a sphere: worst error " << worst << " over " << counted
            << " vertices" << std::endl;
  CHECK(counted > 20);
  CHECK(worst < 0.01); // the tessellation's flatness: a few 1e-3
}

/// A sphere, white below z = 0.3 and red above: the colour maps refine the remesh
/// along the transition, R^6 does not see it; the sampled colours of every face
/// differ by at most h / w_c per channel.
void test_color_maps()
{
  Mesh sphere = make_sphere(1.0, 5);
  auto colors = sphere.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(auto v : vertices(sphere))
    colors[v] = sphere.point(v).z() > 0.3 ? CGAL::IO::Color(255, 0, 0) : CGAL::IO::Color(255, 255, 255);
  const double h = 0.1;
  auto in_band = [](const Mesh& m) {
    std::size_t n = 0;
    for(auto v : vertices(m))
      n += std::abs(m.point(v).z() - 0.3) < 0.1;
    return n;
  };
  Mesh r6, direct, gradient;
  remesh_and_check(sphere, r6,
                   RSR::parameters::range_map(RSR::make_position_normal_range_map(sphere, 1.0, 0.5)).grid_spacing(h));
  auto sampled = direct.add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:color").first;
  const auto direct_map = RSR::make_position_normal_color_range_map(sphere, colors, 1.0, 0.5, 1.0);
  RSR::primal_remesh(sphere, direct, RSR::parameters::range_map(direct_map).grid_spacing(h).vertex_color_map(colors),
                     params::vertex_color_map(sampled));
  Mesh checked;
  remesh_and_check(sphere, checked, RSR::parameters::range_map(direct_map).grid_spacing(h));
  CHECK(fingerprint(checked) == fingerprint(direct));
  remesh_and_check(sphere, gradient,
                   RSR::parameters::range_map(RSR::make_position_normal_color_gradient_range_map(sphere, colors, 1.0, 0.5, 0.05))
                       .grid_spacing(h));
  std::cout << "red/white sphere, vertices within 0.1 of the transition: R^6 " << in_band(r6) << ", R^9 direct "
            << in_band(direct) << ", R^9 gradient " << in_band(gradient) << std::endl;
  CHECK(in_band(direct) > 2 * in_band(r6));
  CHECK(in_band(gradient) > 2 * in_band(r6));
  // bounded colour variation, on the sampled colours
  double worst = 0;
  for(auto f : faces(direct)) {
    std::array<double, 3> low = {{1, 1, 1}}, high = {{0, 0, 0}};
    for(auto v : CGAL::vertices_around_face(halfedge(f, direct), direct))
      for(int c = 0; c < 3; ++c) {
        low[c] = std::min(low[c], sampled[v][c]);
        high[c] = std::max(high[c], sampled[v][c]);
      }
    for(int c = 0; c < 3; ++c)
      worst = std::max(worst, (high[c] - low[c]) / h);
  }
  std::cout << "  largest colour variation on a face: " << worst << " cells" << std::endl;
  CHECK(worst <= 1 + 1e-9);

  // the whole pipeline carries the colours to the quads: red on top, white below
  Mesh quads;
  auto quad_colors = quads.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  RSR::remesh(sphere, quads, RSR::parameters::range_map(direct_map).grid_spacing(h).vertex_color_map(colors),
              params::vertex_color_map(quad_colors));
  std::size_t wrong = 0;
  for(auto v : vertices(quads)) {
    const double z = quads.point(v).z();
    const auto& c = quad_colors[v];
    if(z > 0.4)
      wrong += !(c.r() == 255 && c.g() == 0 && c.b() == 0);
    else if(z < 0.2)
      wrong += !(c.r() == 255 && c.g() == 255 && c.b() == 255);
  }
  std::cout << "  quads: " << num_faces(quads) << ", vertices away from the transition with a wrong colour: "
            << wrong << std::endl;
  CHECK_EQ(wrong, std::size_t(0));
}

/// The view-dependent map on a slab receding from the camera (a floor 20 units deep):
/// faces are bounded in pixels, so they are larger in space far away.
void test_view_map()
{
  std::set<std::array<int, 3>> voxels;
  for(int x = 0; x < 10; ++x)
    for(int z = 0; z < 100; ++z)
      voxels.insert({x, 0, z});
  Mesh slab = make_voxel_surface(voxels, 0.2); // x in [0, 2], y in [0, 0.2], z in [0, 20]
  for(auto v : vertices(slab)) {
    const Point& p = slab.point(v);
    slab.point(v) = Point(p.x() - 1, p.y() - 1.1, -1 - p.z());
  }
  const RSR::Camera camera = RSR::make_look_at_camera({{0, 0, 0}}, {{0, -1, -10}}, {{0, 1, 0}}, 60, 800, 600);
  const RSR::View_range_map<Mesh::Property_map<Mesh::Vertex_index, Point>> f(slab.points(), camera, 10.0);
  const double h = 20; // pixels
  Mesh remesh;
  remesh_and_check(slab, remesh, RSR::parameters::range_map(f).grid_spacing(h));
  // pixel extent of the faces (sampled positions, projected), and their size in space
  double worst_pixels = 0, worst_pixels_beyond_5 = 0, near_size = 0, far_size = 0;
  int near = 0, far = 0;
  for(auto face : faces(remesh)) {
    double low[2] = {1e30, 1e30}, high[2] = {-1e30, -1e30}, zlow = 1e30, zhigh = -1e30, depth = 0;
    int corners = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(face, remesh), remesh)) {
      const Point& p = remesh.point(v);
      const auto& m = camera.view_projection;
      double clip[4];
      for(int r = 0; r < 4; ++r)
        clip[r] = m[4 * r] * p.x() + m[4 * r + 1] * p.y() + m[4 * r + 2] * p.z() + m[4 * r + 3];
      const double pixel[2] = {(clip[0] / clip[3] + 1) / 2 * 800, (clip[1] / clip[3] + 1) / 2 * 600};
      for(int d = 0; d < 2; ++d) {
        low[d] = std::min(low[d], pixel[d]);
        high[d] = std::max(high[d], pixel[d]);
      }
      zlow = std::min(zlow, p.z());
      zhigh = std::max(zhigh, p.z());
      depth += p.z();
      ++corners;
    }
    depth /= corners;
    worst_pixels = std::max({worst_pixels, high[0] - low[0], high[1] - low[1]});
    if(depth < -5)
      worst_pixels_beyond_5 = std::max({worst_pixels_beyond_5, high[0] - low[0], high[1] - low[1]});
    if(depth > -4) {
      near_size += zhigh - zlow;
      ++near;
    } else if(depth < -15) {
      far_size += zhigh - zlow;
      ++far;
    }
  }
  std::cout << "view map: " << num_faces(remesh) << " faces, largest screen extent " << worst_pixels
            << " px, " << worst_pixels_beyond_5 << " px beyond depth 5 (cell " << h << " px); mean depth extent near " << near_size / near << ", far "
            << far_size / far << std::endl;
  CHECK(near > 10 && far > 10);
  // The map is linear on each input triangle, the projection is not: the bound holds
  // for the interpolated pixel coordinates (checked exactly above), and for the true
  // projection where input triangles are small on the screen. Near the camera the
  // slab's triangles (0.2 units) cover up to ~75 px, and a face reaches 1.25 cells.
  CHECK(worst_pixels_beyond_5 < 1.05 * h);
  CHECK(worst_pixels < 1.5 * h);
  CHECK(far_size / far > 4 * near_size / near);

  // a vertex behind the camera is an error
  const RSR::Camera backwards = RSR::make_look_at_camera({{0, 0, -10}}, {{0, 0, 0}}, {{0, 1, 0}}, 60, 800, 600);
  const RSR::View_range_map<Mesh::Property_map<Mesh::Vertex_index, Point>> behind(slab.points(), backwards);
  bool thrown = false;
  try {
    Mesh out;
    RSR::primal_remesh(slab, out, RSR::parameters::range_map(behind).grid_spacing(h));
  } catch(const RSR::Remeshing_error&) {
    thrown = true;
  }
  CHECK(thrown);
}

void check_primal_normals_on_creases(const Mesh& creased);

/// Creases: on a cube, every edge of its sides is a crease; the prepared mesh is the
/// same surface (area, Euler characteristic) with zero-area strips along the 12 edges
/// and a zero-area triangle at each of the 8 corners; the normals on each side are
/// that side's, and the R^6 remesh keeps every invariant on it.
void test_crease_triangles()
{
  const Mesh cube = make_lattice_cube(3);
  Mesh creased;
  const RSR::Crease_statistics stats = RSR::insert_crease_triangles(cube, creased, 30.0);
  std::cout << "cube creases: " << stats.feature_edges << " crease edges, " << stats.added_vertices
            << " added vertices, " << stats.crease_triangles << " zero-area triangles" << std::endl;
  CHECK_EQ(stats.feature_edges, std::size_t(36));
  CHECK_EQ(stats.added_vertices, std::size_t(8 * 2 + 24 * 1));
  CHECK_EQ(stats.crease_triangles, std::size_t(36 * 2 + 8));
  CHECK(CGAL::is_valid_polygon_mesh(creased) && CGAL::is_closed(creased) && CGAL::is_triangle_mesh(creased));
  CHECK_EQ(euler_characteristic(creased), euler_characteristic(cube));
  CHECK(std::abs(CGAL::Polygon_mesh_processing::area(creased) - CGAL::Polygon_mesh_processing::area(cube)) < 1e-9);
  // every vertex's area-weighted normal is an axis (one side's normal)
  const RSR::Lazy_vertex_normal_map<Mesh> normals(creased);
  std::size_t off_axis = 0;
  for(auto v : vertices(creased)) {
    const auto n = get(normals, v);
    off_axis += !(std::abs(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]) - 1) < 1e-12);
  }
  CHECK_EQ(off_axis, std::size_t(0));
  Mesh remesh;
  remesh_and_check(creased, remesh,
                   RSR::parameters::range_map(RSR::make_position_normal_range_map(creased, 1.0, 2.0)).grid_spacing(0.37));
  std::cout << "  R^6 remesh of the creased cube: " << num_vertices(remesh) << " vertices, chi "
            << euler_characteristic(remesh) << std::endl;
  CHECK_EQ(euler_characteristic(remesh), 2L);
  check_primal_normals_on_creases(creased);

  // is_sharp_edge() is the rule insert_crease_triangles() uses: the same 36 edges at
  // 30 degrees, none at 100 (the cube's sides meet at 90); with its own creases in
  // edge_is_constrained_map, the same mesh
  std::size_t sharp_at_30 = 0, sharp_at_100 = 0;
  for(auto e : edges(cube)) {
    sharp_at_30 += RSR::is_sharp_edge(e, cube, 30.0);
    sharp_at_100 += RSR::is_sharp_edge(e, cube, 100.0, CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, cube)));
  }
  CHECK_EQ(sharp_at_30, stats.feature_edges);
  CHECK_EQ(sharp_at_100, std::size_t(0));
  const auto is_crease = boost::make_function_property_map<Mesh::Edge_index, bool>(
      [&cube](Mesh::Edge_index e) { return RSR::is_sharp_edge(e, cube, 30.0); });
  Mesh creased_by_map;
  const RSR::Crease_statistics by_map =
      RSR::insert_crease_triangles(cube, creased_by_map, 0.0, CGAL::parameters::edge_is_constrained_map(is_crease));
  CHECK_EQ(by_map.feature_edges, stats.feature_edges);
  CHECK_EQ(num_faces(creased_by_map), num_faces(creased));
}

/// A primal vertex inside a crease strip or a corner triangle gets one side's normal,
/// not a blend of both (the normal of no surface), and the other side's normal through
/// `vertex_crease_normal_map`; elsewhere that map holds the null vector. On the creased
/// lattice cube [0, 3]^3 every side's normal is an axis, and two sides that meet are
/// perpendicular.
void check_primal_normals_on_creases(const Mesh& creased)
{
  Mesh primal;
  auto normals = primal.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  auto crease_normals = primal.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:crease_normal").first;
  RSR::primal_remesh(creased, primal,
                     RSR::parameters::range_map(RSR::make_position_normal_range_map(creased, 1.0, 2.0)).grid_spacing(0.37),
                     RSR::parameters::vertex_crease_normal_map(crease_normals).vertex_normal_map(normals));
  auto is_axis = [](const K::Vector_3& n) {
    return std::abs(std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z()) - 1) < 1e-12 &&
           std::abs(n.squared_length() - 1) < 1e-12;
  };
  auto on_cube_edge = [](const Point& p) {
    int at_side = 0;
    for(int d = 0; d < 3; ++d)
      at_side += std::abs(p[d]) < 1e-9 || std::abs(p[d] - 3) < 1e-9;
    return at_side >= 2;
  };
  std::size_t off_axis = 0, with_crease_normal = 0, misplaced = 0;
  for(auto v : vertices(primal)) {
    off_axis += !is_axis(normals[v]);
    if(crease_normals[v] == CGAL::NULL_VECTOR)
      continue;
    ++with_crease_normal;
    misplaced += !is_axis(crease_normals[v]) || std::abs(crease_normals[v] * normals[v]) > 1e-12 ||
                 !on_cube_edge(primal.point(v));
  }
  std::cout << "  primal of the creased cube: " << num_vertices(primal) << " vertices, " << with_crease_normal
            << " inside creases, " << off_axis << " normals off the axes" << std::endl;
  CHECK_EQ(off_axis, std::size_t(0));
  CHECK(with_crease_normal >= 24); // at least two per cube edge
  CHECK_EQ(misplaced, std::size_t(0));
}

/// Vertex normals of meshes at extreme scales: unit, or zero where there is no normal,
/// never NaN (the squared length of 1e200 or 1e-200 vectors over- or underflows; at
/// 1e-310, subnormal, the unit-size scale factor 1 / 1e-310 itself overflows).
void test_extreme_normals()
{
  for(double scale : {1e-310, 1e-300, 1e-200, 1e-100, 1.0, 1e100, 1e200}) {
    Mesh sphere = make_sphere(1.0, 2);
    for(auto v : vertices(sphere))
      sphere.point(v) = Point(scale * sphere.point(v).x(), scale * sphere.point(v).y(), scale * sphere.point(v).z());
    const RSR::Lazy_vertex_normal_map<Mesh> normals(sphere);
    double worst = 0; // |1 - |n|| and the angle to the radial direction
    for(auto v : vertices(sphere)) {
      const Point p(sphere.point(v).x() / scale, sphere.point(v).y() / scale, sphere.point(v).z() / scale);
      const double distance = std::sqrt(CGAL::square(p.x()) + CGAL::square(p.y()) + CGAL::square(p.z()));
      // the normal maps' normal, and the one the primal's polygons get in the dual
      for(const auto& n : {get(normals, v), RSR::internal::area_weighted_vertex_normal(
                                                v, sphere, get(CGAL::vertex_point, sphere))}) {
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const double radial = (n[0] * p.x() + n[1] * p.y() + n[2] * p.z()) / distance;
        worst = std::max({worst, std::abs(1 - length), 1 - radial});
        if(!std::isfinite(length) || !std::isfinite(radial))
          worst = std::numeric_limits<double>::infinity();
      }
    }
    std::cout << "normals at scale " << scale << ": worst deviation " << worst << std::endl;
    CHECK(worst < 0.05);
  }
  using RSR::internal::normalized;
  const auto zero = RSR::internal::Vec3{{0, 0, 0}};
  CHECK(normalized({{std::numeric_limits<double>::quiet_NaN(), 1, 1}}) == zero);
  CHECK(normalized({{1, std::numeric_limits<double>::quiet_NaN(), 1}}) == zero);
  CHECK(normalized({{std::numeric_limits<double>::infinity(), 0, 0}}) == zero);
  CHECK(normalized({{0, 0, 0}}) == zero);
}

/// `smooth_vertex_normals()`: each round replaces a normal by the unit sum of its own
/// and its neighbours', all read before any is written; a vanishing sum keeps the
/// normal, a zero normal adds nothing, an isolated vertex keeps its own; on a sphere
/// the averaged normals stay radial (within a degree after the program's 8 rounds).
void test_smooth_vertex_normals()
{
  using Normal = std::array<double, 3>;
  Mesh tetrahedron;
  CGAL::make_tetrahedron(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1), tetrahedron);
  const auto lonely = tetrahedron.add_vertex(Point(5, 5, 5));
  auto normals = tetrahedron.add_property_map<Mesh::Vertex_index, Normal>("v:test_normal").first;
  auto set_all = [&](const Normal& n) {
    for(auto v : vertices(tetrahedron))
      normals[v] = n;
  };
  auto first = *vertices(tetrahedron).begin();
  // every vertex sees all four: (1, 0, 0) + 3 (0, 0, 1), the same for each, normalised
  set_all({{0, 0, 1}});
  normals[first] = {{1, 0, 0}};
  normals[lonely] = {{0, 1, 0}};
  RSR::smooth_vertex_normals(tetrahedron, normals);
  const double unit = 1 / std::sqrt(10.);
  for(auto v : vertices(tetrahedron))
    if(v != lonely) {
      CHECK(std::abs(normals[v][0] - unit) < 1e-15 && normals[v][1] == 0 && std::abs(normals[v][2] - 3 * unit) < 1e-15);
    }
  CHECK(normals[lonely] == (Normal{{0, 1, 0}}));
  // the outward normals of a regular tetrahedron sum to zero: each keeps its own
  for(auto v : vertices(tetrahedron)) {
    const Point& p = tetrahedron.point(v);
    normals[v] = {{p.x() / std::sqrt(3.), p.y() / std::sqrt(3.), p.z() / std::sqrt(3.)}};
  }
  const Normal kept = normals[first];
  RSR::smooth_vertex_normals(tetrahedron, normals, RSR::parameters::number_of_iterations(std::size_t(3)));
  CHECK(normals[first] == kept);
  // ... up to rounding, turned anyhow (the sum about 1e-17 before the rule)
  Mesh turned;
  CGAL::make_tetrahedron(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1), turned);
  auto turned_normals = turned.add_property_map<Mesh::Vertex_index, Normal>("v:test_normal").first;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for(auto v : vertices(turned)) {
    const Point p = turned.point(v);
    turned.point(v) = Point(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z());
    const Point& q = turned.point(v);
    turned_normals[v] = {{q.x() / std::sqrt(3.), q.y() / std::sqrt(3.), q.z() / std::sqrt(3.)}};
  }
  std::vector<Normal> outward;
  for(auto v : vertices(turned))
    outward.push_back(turned_normals[v]);
  RSR::smooth_vertex_normals(turned, turned_normals);
  std::size_t k = 0;
  for(auto v : vertices(turned))
    CHECK(turned_normals[v] == outward[k++]);
  // a zero normal adds nothing, and gets its neighbours' mean
  normals[first] = {{0, 0, 0}};
  std::array<Normal, 3> axes = {{{{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}}};
  std::size_t axis = 0;
  for(auto v : vertices(tetrahedron))
    if(v != first && v != lonely)
      normals[v] = axes[axis++];
  RSR::smooth_vertex_normals(tetrahedron, normals);
  const double third = 1 / std::sqrt(3.);
  CHECK(std::abs(normals[first][0] - third) < 1e-15 && std::abs(normals[first][1] - third) < 1e-15 &&
        std::abs(normals[first][2] - third) < 1e-15);
  // at any scale: a tetrahedron 1e-170 across is smoothed as the one 1 across
  Mesh tiny_tetrahedron = tetrahedron;
  for(auto v : vertices(tiny_tetrahedron)) {
    const Point p = tiny_tetrahedron.point(v);
    tiny_tetrahedron.point(v) = Point(1e-170 * p.x(), 1e-170 * p.y(), 1e-170 * p.z());
  }
  auto tiny_normals = tiny_tetrahedron.add_property_map<Mesh::Vertex_index, Normal>("v:tiny_normal").first;
  for(auto v : vertices(tiny_tetrahedron))
    tiny_normals[v] = {{0, 0, 1}};
  tiny_normals[first] = {{1, 0, 0}};
  RSR::smooth_vertex_normals(tiny_tetrahedron, tiny_normals);
  CHECK(std::abs(tiny_normals[first][0] - unit) < 1e-15 && std::abs(tiny_normals[first][2] - 3 * unit) < 1e-15);
  // no rounds: unchanged; too many: refused, unchanged
  normals[first] = {{0.6, 0, 0.8}};
  RSR::smooth_vertex_normals(tetrahedron, normals, RSR::parameters::number_of_iterations(std::size_t(0)));
  CHECK(normals[first] == (Normal{{0.6, 0, 0.8}}));
  bool refused = false;
  try {
    RSR::smooth_vertex_normals(tetrahedron, normals, RSR::parameters::number_of_iterations(std::size_t(2000000)));
  } catch(const RSR::Remeshing_error& e) {
    refused = e.kind() == RSR::Remeshing_error::Kind::BAD_PARAMETER;
  }
  CHECK(refused);
  CHECK(normals[first] == (Normal{{0.6, 0, 0.8}}));
  for(double bad : {-1., 2.5}) { // ... as a negative or fractional count is
    bool bad_refused = false;
    try {
      RSR::smooth_vertex_normals(tetrahedron, normals, RSR::parameters::number_of_iterations(bad));
    } catch(const RSR::Remeshing_error& e) {
      bad_refused = e.kind() == RSR::Remeshing_error::Kind::BAD_PARAMETER;
    }
    CHECK(bad_refused);
  }
  CHECK(normals[first] == (Normal{{0.6, 0, 0.8}}));
  // a sphere: radial normals stay radial, CGAL vectors as values
  Mesh sphere = make_sphere(1.0, 3);
  auto vectors = sphere.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:test_vector").first;
  RSR::compute_vertex_normals(sphere, vectors);
  RSR::smooth_vertex_normals(sphere, vectors, RSR::parameters::number_of_iterations(std::size_t(8)));
  double worst = 0;
  for(auto v : vertices(sphere)) {
    const K::Vector_3 radial = sphere.point(v) - CGAL::ORIGIN;
    const double cosine = vectors[v] * radial / std::sqrt(radial.squared_length() * vectors[v].squared_length());
    worst = std::max(worst, std::acos(std::min(1., cosine)) * 180 / CGAL_PI);
  }
  std::cout << "averaged normals, sphere, 8 rounds: largest angle to the radius " << worst << " degrees" << std::endl;
  CHECK(worst < 1);
  // a cube opened along its edges: the zero-area crease triangles join no normals, and
  // each side keeps its face's (averaged across the edges, they would turn)
  Mesh opened;
  RSR::insert_crease_triangles(make_lattice_cube(3), opened, 30.0);
  auto sides = opened.add_property_map<Mesh::Vertex_index, Normal>("v:test_normal").first;
  RSR::compute_vertex_normals(opened, sides);
  std::vector<Normal> computed;
  for(auto v : vertices(opened))
    computed.push_back(sides[v]);
  RSR::smooth_vertex_normals(opened, sides, RSR::parameters::number_of_iterations(std::size_t(8)));
  std::size_t moved = 0;
  k = 0;
  for(auto v : vertices(opened)) {
    const Normal& n = sides[v];
    const Normal& was = computed[k++];
    moved += std::abs(n[0] - was[0]) + std::abs(n[1] - was[1]) + std::abs(n[2] - was[2]) > 1e-12;
  }
  std::cout << "averaged normals, opened cube: " << moved << " of " << num_vertices(opened) << " turned" << std::endl;
  CHECK_EQ(moved, std::size_t(0));
}

/// `compute_vertex_normals()` (one pass over the faces) gives the lazy map's normals:
/// both weightings, zero-area crease triangles, an open patch, extreme scales,
/// `std::array` and CGAL vector values; and the remesh with either map is the same.
void test_one_pass_normals()
{
  Mesh creased;
  RSR::insert_crease_triangles(make_lattice_cube(3), creased, 30.0);
  Mesh patch = make_sphere(1.0, 2); // a sphere with a cap removed: a border
  std::vector<Mesh::Face_index> cap;
  for(auto f : faces(patch))
    if(patch.point(target(halfedge(f, patch), patch)).z() > 0.8)
      cap.push_back(f);
  for(auto f : cap)
    CGAL::Euler::remove_face(halfedge(f, patch), patch);
  patch.collect_garbage();
  Mesh tiny = make_ellipsoid(1, 2, 3, 2), huge = tiny;
  for(auto v : vertices(tiny)) {
    const Point p = tiny.point(v);
    tiny.point(v) = Point(1e-200 * p.x(), 1e-200 * p.y(), 1e-200 * p.z());
    huge.point(v) = Point(1e200 * p.x(), 1e200 * p.y(), 1e200 * p.z());
  }
  const std::vector<std::pair<const char*, Mesh*>> meshes = {
      {"creased cube", &creased}, {"open sphere", &patch}, {"tiny ellipsoid", &tiny}, {"huge ellipsoid", &huge}};
  for(const auto& [name, mesh] : meshes)
    for(auto weighting : {RSR::Normal_weighting::AREA, RSR::Normal_weighting::ANGLE}) {
      auto as_arrays = mesh->add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:test_normal").first;
      auto as_vectors = mesh->add_property_map<Mesh::Vertex_index, K::Vector_3>("v:test_vector").first;
      RSR::compute_vertex_normals(*mesh, as_arrays, weighting);
      RSR::compute_vertex_normals(*mesh, as_vectors, weighting);
      const RSR::Lazy_vertex_normal_map<Mesh> lazy(*mesh, weighting);
      double worst = 0;
      for(auto v : vertices(*mesh)) {
        const auto a = get(lazy, v), b = as_arrays[v];
        const K::Vector_3 c = as_vectors[v];
        worst = std::max({worst, std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]),
                          std::abs(c.x() - b[0]) + std::abs(c.y() - b[1]) + std::abs(c.z() - b[2])});
        if(!std::isfinite(b[0] + b[1] + b[2]))
          worst = std::numeric_limits<double>::infinity();
      }
      std::cout << "one-pass normals, " << name << (weighting == RSR::Normal_weighting::AREA ? ", area" : ", angle")
                << ": largest difference to the lazy map " << worst << std::endl;
      CHECK(worst < 1e-12);
      mesh->remove_property_map(as_arrays);
      mesh->remove_property_map(as_vectors);
    }
  // The same remesh from either map. The normals differ by rounding, which decides
  // nothing off the grid's hyperplanes: the grid is shifted off the ellipsoid's planes
  // of symmetry, where normal coordinates vanish (exactly in one map, 1e-17 in the other).
  Mesh ellipsoid = make_ellipsoid(1, 2, 3, 4);
  const std::array<double, 6> origin = {{0.0123, 0.0456, 0.0789, 0.0321, 0.0654, 0.0987}};
  auto normals = ellipsoid.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  RSR::compute_vertex_normals(ellipsoid, normals);
  const RSR::Position_normal_range_map precomputed(get(CGAL::vertex_point, ellipsoid), normals, 1.0, 2.0);
  Mesh from_lazy, from_precomputed;
  RSR::primal_remesh(ellipsoid, from_lazy,
                     RSR::parameters::grid_origin(origin)
                         .range_map(RSR::make_position_normal_range_map(ellipsoid, 1.0, 2.0))
                         .grid_spacing(0.3));
  RSR::primal_remesh(ellipsoid, from_precomputed,
                     RSR::parameters::grid_origin(origin).range_map(precomputed).grid_spacing(0.3));
  CHECK(num_vertices(from_lazy) > 100);
  CHECK_EQ(fingerprint(from_lazy), fingerprint(from_precomputed));

  // the output's normals: interpolated from the input normals the caller gives
  // (np_in), the same as from the remesher's own; a constant map gives its constant
  auto output_normals = [&](const auto& np_in) {
    Mesh out;
    auto n = out.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
    RSR::primal_remesh(ellipsoid, out, np_in, params::vertex_normal_map(n));
    std::vector<K::Vector_3> result;
    for(auto v : vertices(out))
      result.push_back(n[v]);
    return result;
  };
  const auto own = output_normals(params::grid_spacing(0.2));
  const auto given = output_normals(params::grid_spacing(0.2).vertex_normal_map(normals));
  const auto constant = output_normals(params::grid_spacing(0.2).vertex_normal_map(
      CGAL::Constant_property_map<Mesh::Vertex_index, std::array<double, 3>>(std::array<double, 3>{{0, 0, 2}})));
  double largest_difference = 0, off_constant = 0;
  for(std::size_t i = 0; i < own.size(); ++i) {
    largest_difference = std::max(largest_difference, std::sqrt((own[i] - given[i]).squared_length()));
    off_constant = std::max(off_constant, std::sqrt((constant[i] - K::Vector_3(0, 0, 1)).squared_length()));
  }
  std::cout << "output normals from given input normals: " << own.size()
            << " vertices, largest difference to the remesher's own " << largest_difference
            << ", to a constant map's " << off_constant << std::endl;
  CHECK(own.size() > 100 && own.size() == given.size() && own.size() == constant.size());
  CHECK(largest_difference < 1e-12);
  CHECK(off_constant < 1e-15);
}

/// The vertices of `m` above `z` and below `-z`.
std::pair<std::size_t, std::size_t> vertices_above_and_below(const Mesh& m, double z)
{
  std::size_t above = 0, below = 0;
  for(auto v : vertices(m)) {
    above += m.point(v).z() > z;
    below += m.point(v).z() < -z;
  }
  return {above, below};
}

/// The sizing field's solve on a large grid (the edges of a triangulated k x k square,
/// a field from 1 to 5 across it): the multigrid preconditioner is symmetric and
/// positive on vectors off its kernel (conjugate gradients need both), and the solve
/// reaches its residual in a number of iterations that does not grow with the grid
/// (with L's diagonal as preconditioner, it needed hundreds at this size).
void test_sizing_solve()
{
  namespace I = RSR::internal;
  for(const std::size_t k : {60, 360}) {
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    auto at = [k](std::size_t i, std::size_t j) { return j * k + i; };
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t i = 0; i < k; ++i) {
        if(i + 1 < k)
          edges.emplace_back(at(i, j), at(i + 1, j));
        if(j + 1 < k)
          edges.emplace_back(at(i, j), at(i, j + 1));
        if(i + 1 < k && j + 1 < k)
          edges.emplace_back(at(i, j), at(i + 1, j + 1));
      }
    std::vector<double> sizing(k * k);
    std::vector<std::array<double, 1>> f(k * k);
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t i = 0; i < k; ++i) {
        const double x = double(i) / double(k - 1), y = double(j) / double(k - 1);
        sizing[at(i, j)] = 1 + 4 * x * x * (1 - y);
        f[at(i, j)] = {{std::sin(3 * x) + y}};
      }
    const I::Graph_laplacian graph = I::scaled_edge_graph(k * k, edges, sizing);
    I::Aggregation_multigrid preconditioner(graph);
    CHECK(preconditioner.levels() > 2);
    // symmetry and positivity on two vectors of zero mean
    std::vector<double> x(k * k), y(k * k), bx(k * k), by(k * k);
    for(std::size_t i = 0; i < k * k; ++i) {
      x[i] = std::sin(0.37 * double(i)) - std::cos(0.011 * double(i));
      y[i] = std::cos(1.3 * double(i)) * double(i % 7);
    }
    for(auto* v : {&x, &y}) {
      const double mean = std::accumulate(v->begin(), v->end(), 0.) / double(k * k);
      for(double& value : *v)
        value -= mean;
    }
    preconditioner.apply(x, bx);
    preconditioner.apply(y, by);
    const double xby = I::dot(x, by), ybx = I::dot(y, bx);
    CHECK(std::abs(xby - ybx) <= 1e-9 * (std::abs(xby) + std::abs(ybx)));
    CHECK(I::dot(x, bx) > 0 && I::dot(y, by) > 0);
    // the solve of one coordinate, as scaled_differential() sets it up
    std::vector<double> b(k * k, 0.), d(k * k, 0.), ld(k * k);
    for(const auto& [i, j] : edges) {
      const double s = I::edge_scale(sizing, i, j), w = 1 / (s * s);
      b[i] += w * (s - 1) * (f[i][0] - f[j][0]);
      b[j] += w * (s - 1) * (f[j][0] - f[i][0]);
    }
    int iterations = 0;
    CHECK(I::solve_scaled_coordinate(graph, preconditioner, b, d, RSR::internal::Progress(),
                                     I::maximum_multigrid_iterations, iterations));
    graph.multiply(d, ld);
    double residual = 0;
    for(std::size_t i = 0; i < k * k; ++i)
      residual += (b[i] - ld[i]) * (b[i] - ld[i]);
    CHECK(std::sqrt(residual) <= I::sizing_solve_tolerance * std::sqrt(I::dot(b, b)));
    std::cout << "sizing solve on a " << k << " x " << k << " grid: " << preconditioner.levels() << " levels, "
              << iterations << " iterations" << std::endl;
    CHECK(iterations <= 40);
  }
  // vertices without edges (a mesh's removed vertices) do not hold the coarsening back
  {
    const std::size_t k = 100, isolated = 50000;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t i = 0; i < k; ++i) {
        if(i + 1 < k)
          edges.emplace_back(isolated + j * k + i, isolated + j * k + i + 1);
        if(j + 1 < k)
          edges.emplace_back(isolated + j * k + i, isolated + (j + 1) * k + i);
      }
    const I::Graph_laplacian graph = I::scaled_edge_graph(isolated + k * k, edges, std::vector<double>(isolated + k * k, 1.));
    const I::Aggregation_multigrid preconditioner(graph);
    CHECK(preconditioner.levels() > 2);
  }
}

/// A field of 1 with spots of 1e-12 (weights 10^24 apart): the map still shrinks f (it
/// cannot grow anywhere, s <= 1) and fits the differential better than f itself; the
/// multigrid cycle, whose aggregates' sums mix such weights, once made g span 10^7
/// times f there (such fields now take the diagonal).
void test_sizing_field_spots()
{
  const Mesh sphere = make_sphere(1.0, 5);
  const auto f = RSR::make_identity_range_map(get(CGAL::vertex_point, sphere));
  using V = Mesh::Vertex_index;
  const auto spots = boost::make_function_property_map<V>([](V v) { return std::size_t(v) % 10 == 3 ? 1e-12 : 1.; });
  const auto g = RSR::make_sized_range_map(sphere, f, spots);
  auto extent = [&](const auto& map) {
    std::array<double, 3> low{{1e300, 1e300, 1e300}}, high{{-1e300, -1e300, -1e300}};
    for(auto v : vertices(sphere))
      for(int q = 0; q < 3; ++q) {
        low[q] = (std::min)(low[q], get(map, v)[q]);
        high[q] = (std::max)(high[q], get(map, v)[q]);
      }
    return (std::max)({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
  };
  auto misfit = [&](const auto& map) {
    double sum = 0;
    for(auto e : edges(sphere)) {
      const V a = source(e, sphere), b = target(e, sphere);
      const double s = 0.5 * (get(spots, a) + get(spots, b));
      for(int q = 0; q < 3; ++q) {
        const double t = (get(map, b)[q] - get(map, a)[q]) - s * (get(f, b)[q] - get(f, a)[q]);
        sum += t * t / (s * s);
      }
    }
    return sum;
  };
  std::cout << "sizing field with spots of 1e-12: extent of g " << extent(g) << " (f: " << extent(f) << "), misfit "
            << misfit(g) << " (f: " << misfit(f) << ")" << std::endl;
  CHECK(extent(g) <= 1.01 * extent(f));
  CHECK(misfit(g) < misfit(f));
}

/// The sizing field: s = 2 everywhere is the map 2 f, s = 1 is f itself (in R^6 too,
/// and far from the origin, to the last bit), a coordinate f keeps constant stays so,
/// s growing from 1 to 3 between the lower and the upper half of a sphere makes the
/// remesh several times denser above while the lower half stays near the plain one, and
/// a field that is not positive and finite, or a map that is not finite, is refused
/// before any work; the progress visitor may stop the solve.
void test_sizing_field()
{
  const Mesh sphere = make_sphere(1.0, 5);
  const auto vpm = get(CGAL::vertex_point, sphere);
  const auto f = RSR::make_identity_range_map(vpm);
  using V = Mesh::Vertex_index;
  auto constant = [](double s) { return boost::make_function_property_map<V>([s](V) { return s; }); };
  const auto twice = RSR::make_sized_range_map(sphere, f, constant(2.0));
  double error = 0;
  for(auto e : edges(sphere)) {
    const V a = source(e, sphere), b = target(e, sphere);
    for(int q = 0; q < 3; ++q)
      error = (std::max)(error, std::abs((get(twice, b)[q] - get(twice, a)[q]) - 2 * (get(f, b)[q] - get(f, a)[q])));
  }
  CHECK(error < 1e-6);
  // far from the origin, a field of 1 is f and a constant one c f, to the last bit (the
  // solve's residual once cancelled 1e5-sized coordinates: 3,000 times the edges' error)
  Mesh far = sphere;
  for(auto v : vertices(far))
    far.point(v) = Point(1e5 + 1e-4 * sphere.point(v).x(), 1e-4 * sphere.point(v).y(), 1e-4 * sphere.point(v).z());
  const auto far_f = RSR::make_identity_range_map(get(CGAL::vertex_point, far));
  for(double c : {1., 3., 1e-200}) {
    const auto scaled = RSR::make_sized_range_map(far, far_f, constant(c));
    bool exact = true;
    for(auto v : vertices(far))
      for(int q = 0; q < 3; ++q)
        exact = exact && get(scaled, v)[q] == c * get(far_f, v)[q];
    CHECK(exact);
  }
  // a plane at an inexact height with a field of two values: g stays one plane
  Mesh plane;
  const int n = 30;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      plane.add_vertex(Point(512345.678 + i, 4612345.678 + j, 100.1));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const auto corner = [&](int x, int y) { return V(Mesh::size_type(y * (n + 1) + x)); };
      const V a = corner(i, j), b = corner(i + 1, j), c = corner(i, j + 1), d = corner(i + 1, j + 1);
      plane.add_face(a, b, d);
      plane.add_face(a, d, c);
    }
  const auto plane_f = RSR::make_identity_range_map(get(CGAL::vertex_point, plane));
  const auto halves = boost::make_function_property_map<V>([&](V v) { return plane.point(v).x() < 512360 ? 1. : 2.; });
  const auto plane_g = RSR::make_sized_range_map(plane, plane_f, halves);
  bool flat = true;
  for(auto v : vertices(plane))
    flat = flat && get(plane_g, v)[2] == get(plane_g, *vertices(plane).begin())[2];
  CHECK(flat);

  const auto position_normal = RSR::make_position_normal_range_map(sphere, 1.0, 0.5);
  const auto same = RSR::make_sized_range_map(sphere, position_normal, constant(1.0));
  bool unchanged = true;
  for(auto v : vertices(sphere))
    unchanged = unchanged && get(same, v) == get(position_normal, v);
  CHECK(unchanged);

  const auto upper_half_finer =
      boost::make_function_property_map<V>([&](V v) { return 2 + std::tanh(get(vpm, v).z() / 0.1); });
  const auto np = RSR::parameters::grid_spacing(0.1);
  Mesh plain, sized, sized_by_hand;
  RSR::remesh(sphere, plain, np);
  RSR::remesh(sphere, sized, np.sizing_field(upper_half_finer));
  RSR::remesh(sphere, sized_by_hand, np.range_map(RSR::make_sized_range_map(sphere, f, upper_half_finer)));
  const auto [plain_above, plain_below] = vertices_above_and_below(plain, 0.3);
  const auto [above, below] = vertices_above_and_below(sized, 0.3);
  std::cout << "sizing field: above/below " << plain_above << "/" << plain_below << " -> " << above << "/" << below
            << std::endl;
  CHECK(plain_above < 1.25 * double(plain_below) && plain_below < 1.25 * double(plain_above));
  CHECK(double(above) > 3 * double(below));
  CHECK(double(above) > 3 * double(plain_above));
  CHECK(double(below) < 1.5 * double(plain_below));
  CHECK_EQ(fingerprint(sized), fingerprint(sized_by_hand));
  CHECK_EQ(euler_characteristic(sized), 2);

  using Kind = RSR::Remeshing_error::Kind;
  const V first = *vertices(sphere).begin();
  for(double wrong : {0., -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const auto field = boost::make_function_property_map<V>([&](V v) { return v == first ? wrong : 1.; });
    Mesh kept = plain;
    Kind kind = Kind::CANCELLED;
    try {
      RSR::remesh(sphere, kept, np.sizing_field(field));
    } catch(const RSR::Remeshing_error& e) {
      kind = e.kind();
    }
    CHECK(kind == Kind::BAD_PARAMETER);
    CHECK_EQ(fingerprint(kept), fingerprint(plain));
  }
  // the visitor hears of the solve and may stop it: the output is then left empty
  std::vector<RSR::Remeshing_stage> heard;
  auto stop = [&](RSR::Remeshing_stage stage, double) {
    heard.push_back(stage);
    return false;
  };
  bool stopped = false;
  try {
    RSR::make_sized_range_map(sphere, f, upper_half_finer, RSR::parameters::progress_visitor(stop));
  } catch(const RSR::Remeshing_cancelled&) {
    stopped = true;
  }
  CHECK(stopped && heard.size() == 1 && heard[0] == RSR::Remeshing_stage::SCAN);
  Mesh emptied = plain;
  stopped = false;
  try {
    RSR::remesh(sphere, emptied, np.sizing_field(upper_half_finer).progress_visitor(stop));
  } catch(const RSR::Remeshing_cancelled&) {
    stopped = true;
  }
  CHECK(stopped && num_vertices(emptied) == 0);
  // a bad cell size or grid origin is refused before the solve (the visitor hears
  // nothing) and before the output is touched, with or without a field
  for(int bad = 0; bad < 4; ++bad) {
    const bool bad_origin = bad == 1;
    heard.clear();
    Mesh kept = plain;
    Kind kind = Kind::CANCELLED;
    const auto listen = [&](RSR::Remeshing_stage stage, double) {
      heard.push_back(stage);
      return true;
    };
    try {
      if(bad_origin)
        RSR::primal_remesh(sphere, kept,
                           np.sizing_field(upper_half_finer)
                               .grid_origin(std::array<double, 3>{{0., std::numeric_limits<double>::quiet_NaN(), 0.}})
                               .progress_visitor(listen));
      else if(bad == 0)
        RSR::remesh(sphere, kept, RSR::parameters::grid_spacing(-1.).sizing_field(upper_half_finer).progress_visitor(listen));
      else if(bad == 2)
        RSR::remesh(sphere, kept, RSR::parameters::grid_spacing(0.).progress_visitor(listen));
      else
        RSR::primal_remesh(sphere, kept,
                           RSR::parameters::grid_spacing(std::numeric_limits<double>::infinity()).progress_visitor(listen));
    } catch(const RSR::Remeshing_error& e) {
      kind = e.kind();
    }
    CHECK(kind == Kind::BAD_PARAMETER);
    CHECK(heard.empty());
    CHECK_EQ(fingerprint(kept), fingerprint(plain));
  }
  // a failed target search leaves the output empty, not with the last size it tried
  {
    Mesh emptied_by_search = plain;
    Kind kind = Kind::CANCELLED;
    try {
      RSR::remesh(sphere, emptied_by_search, RSR::parameters::number_of_target_vertices(3));
    } catch(const RSR::Remeshing_error& e) {
      kind = e.kind();
    }
    CHECK(kind == Kind::TARGET_NOT_REACHED);
    CHECK_EQ(num_vertices(emptied_by_search), 0u);
  }
  // values too far apart for the weights 1 / s^2 to stay doubles
  const auto too_wide = boost::make_function_property_map<V>([&](V v) { return v == first ? 1e-13 : 1.; });
  Kind wide_kind = Kind::CANCELLED;
  try {
    RSR::make_sized_range_map(sphere, f, too_wide);
  } catch(const RSR::Remeshing_error& e) {
    wide_kind = e.kind();
  }
  CHECK(wide_kind == Kind::BAD_PARAMETER);
  const auto not_finite = boost::make_function_property_map<V>([&](V v) {
    auto value = get(f, v);
    value[1] = v == first ? std::numeric_limits<double>::infinity() : value[1];
    return value;
  });
  Kind kind = Kind::CANCELLED;
  try {
    RSR::make_sized_range_map(sphere, not_finite, constant(1.0));
  } catch(const RSR::Remeshing_error& e) {
    kind = e.kind();
  }
  CHECK(kind == Kind::BAD_INPUT);
}

int main()
{
  test_sizing_field();
  test_sizing_solve();
  test_sizing_field_spots();
  test_gauss_map_anisotropy();
  test_position_normal_weights();
  test_bounded_position_variation();
  test_color_gradient_magnitudes();
  test_color_maps();
  test_view_map();
  test_crease_triangles();
  test_extreme_normals();
  test_one_pass_normals();
  test_smooth_vertex_normals();
  return report("test_range_maps");
}
