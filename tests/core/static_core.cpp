/// Compile-only suite for the compile-time core: every check is a static_assert, so a broken
/// identity fails the default build. Expected values are exact mathematics (rational
/// identities, polynomial reproduction) or the LPF paper's printed formulas (section 3.1).

#include <geomint/geomint.hpp>

#include <array>
#include <cstddef>
#include <utility>

namespace {
using geomint::rational;
using geomint::polynomial;

// ---------------------------------------------------------------- rational
static_assert(rational(6, 4) == rational(3, 2), "reduced on construction");
static_assert(rational(3, -6).num == -1 && rational(3, -6).den == 2, "sign on the numerator");
static_assert(rational(1, 3) + rational(1, 6) == rational(1, 2));
static_assert(rational(1, 3) - rational(1, 2) == rational(-1, 6));
static_assert(rational(2, 3) * rational(9, 4) == rational(3, 2));
static_assert(rational(2, 3) / rational(4, 9) == rational(3, 2));
static_assert(rational(1, 3) < rational(1, 2) && rational(-1, 2) < rational(-1, 3));
static_assert(-rational(5, 7) == rational(-5, 7) && geomint::abs(rational(-5, 7)) == rational(5, 7));
// 2^62 / 3 * 3 = 2^62: intermediates above 64 bits are fine when the result fits.
static_assert(rational(std::int64_t(1) << 62, 3) * rational(3) == rational(std::int64_t(1) << 62));
/// Reduction happens in 128 bits before narrowing: (2^40/3^5)(3^5/2^20) = 2^20.
static_assert(rational(std::int64_t(1) << 40, 243) * rational(243, std::int64_t(1) << 20) ==
              rational(std::int64_t(1) << 20));

/// rational is structural: usable as a template argument.
template <rational R>
struct tagged {
  static constexpr rational value = R;
};
static_assert(tagged<rational(1, 2)>::value + tagged<rational(1, 3)>::value == rational(5, 6));

// ---------------------------------------------------------------- polynomial
constexpr polynomial<rational, 1> t_minus_one({rational(-1), rational(1)});  // t - 1
constexpr polynomial<rational, 1> t_plus_one({rational(1), rational(1)});    // t + 1
constexpr auto t2_minus_one = t_minus_one * t_plus_one;                         // t^2 - 1
static_assert(t2_minus_one == polynomial<rational, 2>({rational(-1), rational(0), rational(1)}));
static_assert(t2_minus_one.degree() == 2 && polynomial<rational, 3>().degree() == -1);
static_assert(t2_minus_one(rational(3)) == rational(8));
static_assert(t_minus_one + t_plus_one == polynomial<rational, 1>({rational(0), rational(2)}));
static_assert(t2_minus_one - t_plus_one * t_plus_one == polynomial<rational, 1>({rational(-2), rational(-2)}));
static_assert(geomint::derivative(t2_minus_one) == polynomial<rational, 1>({rational(0), rational(2)}));
static_assert(geomint::derivative<2>(t2_minus_one) == polynomial<rational, 0>(rational(2)));
static_assert(geomint::derivative<3>(t2_minus_one) == polynomial<rational, 0>());
static_assert(geomint::derivative(geomint::antiderivative(t2_minus_one)) == t2_minus_one);
/// int_0^1 t^k dt = 1/(k+1)
static_assert(geomint::integral(polynomial<rational, 5>::monomial(5), rational(0), rational(1)) == rational(1, 6));
static_assert(geomint::integral(t2_minus_one, rational(-1), rational(2)) == rational(0));
/// (t^2 - 1)(2t + 1) = 4t^2 + 4t: composition with an affine map.
static_assert(geomint::compose_affine(t2_minus_one, rational(2), rational(1)) ==
              polynomial<rational, 2>({rational(0), rational(4), rational(4)}));
static_assert(t2_minus_one * rational(3) / rational(3) == t2_minus_one);

// ---------------------------------------------------------------- nodes
static_assert(geomint::nodes<geomint::equispaced, 4, rational>()[1] == rational(1, 4));
static_assert(geomint::nodes<geomint::equispaced, 3, rational>()[2] == rational(2, 3));

/// Floating families are constexpr in double: increasing, with the ends in place and the
/// centre node exactly 1/2 when there is one.
template <class Family, int M>
constexpr bool floating_nodes_are_ordered() {
  constexpr auto c = geomint::nodes<Family, M, double>();
  if (c[0] != 0.0 || c[M] != 1.0) return false;
  for (int a = 0; a < M; ++a)
    if (!(c[static_cast<std::size_t>(a)] < c[static_cast<std::size_t>(a + 1)])) return false;
  if (M % 2 == 0 && c[M / 2] != 0.5) return false;
  return true;
}
template <class Family, int... Ms>
constexpr bool all_ordered(std::integer_sequence<int, Ms...>) {
  return (floating_nodes_are_ordered<Family, Ms + 1>() && ...);
}
static_assert(all_ordered<geomint::gauss_lobatto>(std::make_integer_sequence<int, geomint::max_floating_m>{}));
static_assert(all_ordered<geomint::chebyshev_lobatto>(std::make_integer_sequence<int, geomint::max_floating_m>{}));
static_assert(all_ordered<geomint::gauss_interior>(std::make_integer_sequence<int, geomint::max_floating_m>{}));
static_assert(all_ordered<geomint::equispaced>(std::make_integer_sequence<int, geomint::max_floating_m>{}));
/// m = 2: every family's centre node is 1/2; m = 3 Gauss interior: the Gauss points of P_2,
/// (1 -+ 1/sqrt(3))/2, satisfy (2c - 1)^2 = 1/3.
static_assert(geomint::nodes<geomint::gauss_lobatto, 2, double>()[1] == 0.5);
static_assert([] {
  constexpr auto c = geomint::nodes<geomint::gauss_interior, 3, long double>();
  const long double x = 2 * c[1] - 1;
  const long double defect = 3 * x * x - 1;
  return defect < 8 * std::numeric_limits<long double>::epsilon() &&
         -defect < 8 * std::numeric_limits<long double>::epsilon();
}());

// ---------------------------------------------------------------- differentiation weights, m = 2
/// The LPF paper, section 3.1: xdot(t_k) = (-3 x^k + 4 eta - x^{k+1}) / tau and
/// xddot = (4 x^k - 8 eta + 4 x^{k+1}) / tau^2 at every node.
constexpr auto D1_m2 = geomint::differentiation_weights<1, geomint::equispaced, 2, rational>();
constexpr auto D2_m2 = geomint::differentiation_weights<2, geomint::equispaced, 2, rational>();
static_assert(D1_m2[0][0] == rational(-3) && D1_m2[0][1] == rational(4) && D1_m2[0][2] == rational(-1));
static_assert(D1_m2[2][0] == rational(1) && D1_m2[2][1] == rational(-4) && D1_m2[2][2] == rational(3));
static_assert([] {
  for (const auto& row : D2_m2)
    if (!(row[0] == rational(4) && row[1] == rational(-8) && row[2] == rational(4))) return false;
  return true;
}());

/// Nodes of no family, 0, 1/3, 1 (differentiation_weights_at): l_j' by hand from
/// l_0 = 3 (t - 1/3)(t - 1), l_1 = -9/2 t (t - 1), l_2 = 3/2 t (t - 1/3), i.e. l_0' = 6t - 4,
/// l_1' = 9/2 - 9t, l_2' = 3t - 1/2; Bernstein b_0' = -2(1 - t), b_1' = 2 - 4t, b_2' = 2t at 1/3.
constexpr std::array<rational, 3> uneven_nodes{rational(0), rational(1, 3), rational(1)};
constexpr auto D1_uneven = geomint::differentiation_weights_at<1, geomint::lagrange>(uneven_nodes);
static_assert(D1_uneven[0][0] == rational(-4) && D1_uneven[0][1] == rational(9, 2) && D1_uneven[0][2] == rational(-1, 2));
static_assert(D1_uneven[1][0] == rational(-2) && D1_uneven[1][1] == rational(3, 2) && D1_uneven[1][2] == rational(1, 2));
static_assert(D1_uneven[2][0] == rational(2) && D1_uneven[2][1] == rational(-9, 2) && D1_uneven[2][2] == rational(5, 2));
constexpr auto B1_uneven = geomint::differentiation_weights_at<1, geomint::bernstein>(uneven_nodes);
static_assert(B1_uneven[1][0] == rational(-4, 3) && B1_uneven[1][1] == rational(2, 3) && B1_uneven[1][2] == rational(2, 3));
/// lagrange_values_at on the same nodes, from the l_j above: at 1/2 (-1/4, 9/8, 1/8), at 2
/// (outside the nodes: 5, -9, 5), at the node 1/3 exactly (0, 1, 0).
constexpr auto l_half = geomint::lagrange_values_at(uneven_nodes, rational(1, 2));
static_assert(l_half[0] == rational(-1, 4) && l_half[1] == rational(9, 8) && l_half[2] == rational(1, 8));
constexpr auto l_two = geomint::lagrange_values_at(uneven_nodes, rational(2));
static_assert(l_two[0] == rational(5) && l_two[1] == rational(-9) && l_two[2] == rational(5));
constexpr auto l_node = geomint::lagrange_values_at(uneven_nodes, rational(1, 3));
static_assert(l_node[0] == rational(0) && l_node[1] == rational(1) && l_node[2] == rational(0));

// ---------------------------------------------------------------- identities for m = 1..max_exact_m
/// sum_a l_a = 1 and sum_a c_a^k l_a(t) = t^k as polynomials, k <= m (polynomial reproduction).
template <int M>
constexpr bool lagrange_reproduces_monomials() {
  constexpr auto c = geomint::nodes<geomint::equispaced, M, rational>();
  constexpr auto l = geomint::lagrange_basis<geomint::equispaced, M, rational>();
  for (int k = 0; k <= M; ++k) {
    polynomial<rational, M> sum;
    for (int a = 0; a <= M; ++a) {
      rational ck(1);
      for (int i = 0; i < k; ++i) ck *= c[static_cast<std::size_t>(a)];
      sum += l[static_cast<std::size_t>(a)] * ck;
    }
    if (!(sum == polynomial<rational, M>::monomial(k))) return false;
  }
  // l_a(c_b) = delta_ab
  for (int a = 0; a <= M; ++a)
    for (int b = 0; b <= M; ++b)
      if (!(l[static_cast<std::size_t>(a)](c[static_cast<std::size_t>(b)]) == rational(a == b ? 1 : 0))) return false;
  return true;
}

/// Bernstein: partition of unity, b_{a,m}(0) = delta_{a0}, b_{a,m}(1) = delta_{am}, and
/// sum_a (a/m) b_{a,m} = t (linear precision).
template <int M>
constexpr bool bernstein_identities() {
  constexpr auto b = geomint::bernstein_basis<M, rational>();
  polynomial<rational, M> sum, linear;
  for (int a = 0; a <= M; ++a) {
    sum += b[static_cast<std::size_t>(a)];
    linear += b[static_cast<std::size_t>(a)] * rational(a, M);
    if (!(b[static_cast<std::size_t>(a)](rational(0)) == rational(a == 0 ? 1 : 0))) return false;
    if (!(b[static_cast<std::size_t>(a)](rational(1)) == rational(a == M ? 1 : 0))) return false;
  }
  return sum == polynomial<rational, 0>(rational(1)) && linear == polynomial<rational, 1>::monomial(1);
}

/// D_1 and D_2 applied to node values of t^k give k c^(k-1) and k(k-1) c^(k-2) exactly, and
/// D_{m+1} vanishes (degree-m paths).
template <int M>
constexpr bool weights_differentiate_monomials() {
  constexpr auto c = geomint::nodes<geomint::equispaced, M, rational>();
  constexpr auto D1 = geomint::differentiation_weights<1, geomint::equispaced, M, rational>();
  constexpr auto D2 = geomint::differentiation_weights<2, geomint::equispaced, M, rational>();
  constexpr auto D_high = geomint::differentiation_weights<M + 1, geomint::equispaced, M, rational>();
  auto power = [](rational x, int k) {
    rational out(1);
    for (int i = 0; i < k; ++i) out *= x;
    return out;
  };
  for (int k = 0; k <= M; ++k) {
    for (int i = 0; i <= M; ++i) {
      rational first(0), second(0), high(0);
      for (int j = 0; j <= M; ++j) {
        const rational value = power(c[static_cast<std::size_t>(j)], k);
        first += D1[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * value;
        second += D2[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * value;
        high += D_high[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * value;
      }
      const rational ci = c[static_cast<std::size_t>(i)];
      if (!(first == (k >= 1 ? rational(k) * power(ci, k - 1) : rational(0)))) return false;
      if (!(second == (k >= 2 ? rational(k * (k - 1)) * power(ci, k - 2) : rational(0)))) return false;
      if (!(high == rational(0))) return false;
    }
  }
  return true;
}

/// Bernstein weights: the control points (j/m) describe t, so D_1 gives 1 and D_2 gives 0 at
/// every node; D_0 rows are the basis values (rows sum to 1).
template <int M>
constexpr bool bernstein_weights_identities() {
  constexpr auto D0 = geomint::differentiation_weights<0, geomint::equispaced, M, rational, geomint::bernstein>();
  constexpr auto D1 = geomint::differentiation_weights<1, geomint::equispaced, M, rational, geomint::bernstein>();
  constexpr auto D2 = geomint::differentiation_weights<2, geomint::equispaced, M, rational, geomint::bernstein>();
  for (int i = 0; i <= M; ++i) {
    rational row(0), slope(0), curvature(0);
    for (int j = 0; j <= M; ++j) {
      row += D0[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      slope += D1[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * rational(j, M);
      curvature += D2[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * rational(j, M);
    }
    if (!(row == rational(1) && slope == rational(1) && curvature == rational(0))) return false;
  }
  return true;
}

template <int... Ms>
constexpr bool all_exact_identities(std::integer_sequence<int, Ms...>) {
  return ((lagrange_reproduces_monomials<Ms + 1>() && bernstein_identities<Ms + 1>() &&
           weights_differentiate_monomials<Ms + 1>() && bernstein_weights_identities<Ms + 1>()) &&
          ...);
}
static_assert(all_exact_identities(std::make_integer_sequence<int, geomint::max_exact_m>{}),
              "exact identities for m = 1..max_exact_m");

/// The same reproduction holds for double weights on every family to a few ulps: D_1 applied
/// to c^2 gives 2c (a compile-time check that the constexpr floating path works).
template <class Family, int M>
constexpr bool double_weights_differentiate_square() {
  constexpr auto c = geomint::nodes<Family, M, double>();
  constexpr auto D1 = geomint::differentiation_weights<1, Family, M, double>();
  for (int i = 0; i <= M; ++i) {
    double first = 0;
    for (int j = 0; j <= M; ++j)
      first += D1[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * c[static_cast<std::size_t>(j)] *
               c[static_cast<std::size_t>(j)];
    const double error = first - 2 * c[static_cast<std::size_t>(i)];
    // |D1| is at most about m^2, so rounding stays below 64 m^2 ulps.
    if (error > 64 * M * M * std::numeric_limits<double>::epsilon() ||
        -error > 64 * M * M * std::numeric_limits<double>::epsilon())
      return false;
  }
  return true;
}
static_assert(double_weights_differentiate_square<geomint::gauss_lobatto, 12>());
static_assert(double_weights_differentiate_square<geomint::chebyshev_lobatto, 12>());
static_assert(double_weights_differentiate_square<geomint::gauss_interior, 12>());

}  // namespace

// The Radau families' interior polynomials, exactly: Radau IIA with 3 stages has the nodes
// (4 -+ sqrt 6)/10 and 1, Radau IA 0 and (6 -+ sqrt 6)/10 (Hairer & Wanner II, section IV.5), so
// the interior nodes are the roots of 10 c^2 - 8 c + 1 and 10 c^2 - 12 c + 3.
constexpr auto radau_right_3 = geomint::radau_right::interior_polynomial<rational, 4>(3);
constexpr auto radau_left_3 = geomint::radau_left::interior_polynomial<rational, 4>(3);
static_assert(radau_right_3[0] * rational(10) == radau_right_3[2] && radau_right_3[1] * rational(10) == radau_right_3[2] * rational(-8) &&
              radau_right_3[3] == rational(0));
static_assert(radau_left_3[0] * rational(10) == radau_left_3[2] * rational(3) && radau_left_3[1] * rational(10) == radau_left_3[2] * rational(-12) &&
              radau_left_3[3] == rational(0));
static_assert(geomint::node_family<geomint::radau_right> && !geomint::radau_right::symmetric);
