#pragma once
/// The staggered grid of the beam paper (eq. 46-48): momenta mu_j at the nodes s_j = j ds,
/// j = 0..J, strains gamma_{j+1/2} on the segments between them, j = 0..J-1, and the two
/// ghost segments gamma_{-1/2} = gamma_{J+1/2} = 0 of the free ends (eq. 56).

#include <stdexcept>

namespace geomint::beam {

template <class T>
struct staggered_grid {
  T length;      ///< beam length l
  int segments;  ///< J: number of interior segments; there are J + 1 nodes

  staggered_grid(const T& l, int J) : length(l), segments(J) {
    // l - l == 0 holds for finite l only (inf - inf and NaN - NaN are NaN).
    if (!(l > T(0)) || !(l - l == T(0)))
      throw std::invalid_argument("geomint::beam::staggered_grid: the length must be finite and positive");
    if (J < 1) throw std::invalid_argument("geomint::beam::staggered_grid: need at least 2 nodes (J >= 1)");
  }
  int nodes() const { return segments + 1; }
  T ds() const { return length / T(segments); }
  /// Arc length of node j.
  T node_s(int j) const { return T(j) * length / T(segments); }
  /// Arc length of the midpoint of segment j + 1/2.
  T segment_s(int j) const { return (T(2 * j + 1) * length) / T(2 * segments); }
};

}  // namespace geomint::beam
