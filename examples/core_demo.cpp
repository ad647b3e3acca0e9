/// Prints the node sets, Lagrange bases and differentiation weights for m = 2..6 (exact
/// rationals for equispaced nodes, 20 significant digits for the irrational families).
#include <geomint/geomint.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/legendre.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>
#include <iomanip>
#include <iostream>
#include <utility>

namespace {

template <class T>
void print_value(const T& v) {
  if constexpr (std::is_same_v<T, geomint::rational>)
    std::cout << std::setw(10) << v.str();
  else
    std::cout << std::setw(24) << std::setprecision(20) << v;
}

template <class T, int M>
void print_polynomial(const geomint::polynomial<T, M>& p) {
  bool first = true;
  for (int k = 0; k <= M; ++k) {
    if (p[k] == T(0)) continue;
    std::cout << (first ? "" : " + ");
    if constexpr (std::is_same_v<T, geomint::rational>)
      std::cout << "(" << p[k].str() << ")";
    else
      std::cout << "(" << std::setprecision(12) << p[k] << ")";
    if (k >= 1) std::cout << " t";
    if (k >= 2) std::cout << "^" << k;
    first = false;
  }
  std::cout << "\n";
}

template <class Family, int M, class T>
void print_family() {
  std::cout << "--- " << Family::name << ", m = " << M << " ---\nnodes c_a:";
  for (const auto& c : geomint::nodes<Family, M, T>()) {
    std::cout << ' ';
    print_value(c);
  }
  std::cout << "\nLagrange basis (eq. 8):\n";
  const auto basis = geomint::lagrange_basis<Family, M, T>();
  for (int a = 0; a <= M; ++a) {
    std::cout << "  l_" << a << "(t) = ";
    print_polynomial(basis[static_cast<std::size_t>(a)]);
  }
  const auto print_matrix = [](const char* title, const auto& D) {
    std::cout << title << "\n";
    for (const auto& row : D) {
      std::cout << " ";
      for (const auto& v : row) {
        std::cout << ' ';
        print_value(v);
      }
      std::cout << "\n";
    }
  };
  print_matrix("D1[i][j] = l_j'(c_i):", geomint::differentiation_weights<1, Family, M, T>());
  print_matrix("D2[i][j] = l_j''(c_i):", geomint::differentiation_weights<2, Family, M, T>());
}

template <int... Ms>
void print_all(std::integer_sequence<int, Ms...>) {
  (print_family<geomint::equispaced, Ms + 2, geomint::rational>(), ...);
  (print_family<geomint::gauss_lobatto, Ms + 2, long double>(), ...);
  (print_family<geomint::chebyshev_lobatto, Ms + 2, long double>(), ...);
  (print_family<geomint::gauss_interior, Ms + 2, long double>(), ...);
}

/// Largest |c_a - reference_a| / eps over the nodes of one family, m, scalar type. References:
/// Chebyshev sin^2(pi a / 2m); Gauss interior (1 -+ x)/2 from Boost.Math's legendre_p_zeros.
template <class Family, int M, class T>
double max_error_in_eps() {
  using std::abs;
  using std::sin;
  const auto c = geomint::nodes<Family, M, T>();
  std::vector<T> reference;
  if constexpr (std::is_same_v<Family, geomint::chebyshev_lobatto>) {
    for (int a = 0; a <= M; ++a) {
      const T s = sin(T(boost::math::constants::pi<T>() * T(a) / T(2 * M)));
      reference.push_back(T(s * s));
    }
  } else {
    reference = {T(0), T(1)};
    for (const T& x : boost::math::legendre_p_zeros<T>(M - 1)) {
      reference.push_back(T((T(1) - x) / T(2)));
      if (x != T(0)) reference.push_back(T((T(1) + x) / T(2)));
    }
    std::sort(reference.begin(), reference.end());
  }
  T worst(0);
  for (std::size_t a = 0; a < c.size(); ++a) worst = std::max(worst, T(abs(T(c[a] - reference[a]))));
  return static_cast<double>(worst / std::numeric_limits<T>::epsilon());
}

template <class T, int... Ms>
void print_accuracy_row(const char* type_name, std::integer_sequence<int, Ms...>) {
  std::cout << std::setw(18) << type_name << " | chebyshev max error / eps:";
  ((std::cout << ' ' << std::setprecision(2) << max_error_in_eps<geomint::chebyshev_lobatto, Ms + 2, T>()), ...);
  std::cout << "\n" << std::setw(18) << "" << " | gauss-interior max error / eps:";
  ((std::cout << ' ' << std::setprecision(2) << max_error_in_eps<geomint::gauss_interior, Ms + 2, T>()), ...);
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") != 0) std::cerr << "geomint-core-demo: unknown argument '" << argv[i] << "'\n";
    std::cerr << "usage: geomint-core-demo\n  prints nodes, Lagrange bases and D1/D2 weights for m = 2..6\n";
    return std::strcmp(argv[i], "--help") == 0 ? 0 : 2;
  }
  print_all(std::make_integer_sequence<int, 5>{});
  std::cout << "--- node accuracy against independent references, m = 2..16 ---\n";
  print_accuracy_row<double>("double", std::make_integer_sequence<int, 15>{});
  print_accuracy_row<boost::multiprecision::cpp_bin_float_50>("cpp_bin_float_50", std::make_integer_sequence<int, 15>{});
  print_accuracy_row<boost::multiprecision::cpp_bin_float_100>("cpp_bin_float_100", std::make_integer_sequence<int, 15>{});
  return 0;
}
