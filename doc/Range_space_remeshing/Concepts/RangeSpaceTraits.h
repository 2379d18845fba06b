/*!
\ingroup PkgRangeSpaceRemeshingConcepts
\cgalConcept

The concept `RangeSpaceTraits` describes what the tracer of the package needs from
the range space \f$\mathbb{R}^D\f$: its point type and two exact orientation
predicates on coordinates picked from such points (coordinate projections).

All combinatorial decisions of the remeshing are signs of these predicates,
evaluated on the mapped and scaled input coordinates (doubles) and on integer
lattice levels. The package breaks their ties itself, by a symbolic perturbation
of the grid, so a model only has to return exact signs; it must not break ties.

\cgalHasModel `CGAL::Range_space_remeshing::Range_space_traits<D, K>`
*/
class RangeSpaceTraits
{
public:
  /// \name Types
  /// @{

  /// The dimension D of the range space, 3 <= D <= 16.
  static constexpr int dimension;

  /// A point of the range space: `std::array<double, dimension>`.
  typedef unspecified_type Point_d;

  /*!
  A function object with
  `CGAL::Orientation operator()(double ax, double ay, double bx, double by, double cx, double cy) const`
  returning the exact sign of the orientation of the three points
  (ax, ay), (bx, by), (cx, cy) of the plane: `CGAL::LEFT_TURN` when they turn
  counter-clockwise.
  */
  typedef unspecified_type Orientation_2;

  /*!
  A function object with
  `CGAL::Orientation operator()(const std::array<double,3>& a, const std::array<double,3>& b, const std::array<double,3>& c, const std::array<double,3>& d) const`
  returning the exact sign of the determinant of (b - a, c - a, d - a):
  `CGAL::POSITIVE` when d is on the positive side of the oriented plane (a, b, c).
  */
  typedef unspecified_type Orientation_3;

  /// @}

  /// \name Operations
  /// @{
  /*! the `Orientation_2` predicate */
  Orientation_2 orientation_2_object() const;
  /*! the `Orientation_3` predicate */
  Orientation_3 orientation_3_object() const;
  /// @}
};
