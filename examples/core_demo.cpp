/// Prints the node sets, Lagrange bases and differentiation weights for m = 2..6 (exact
/// rationals for equispaced nodes, 20 significant digits for the irrational families).
#include <geomint/geomint.hpp>

#include <cstring>
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

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") != 0) std::cerr << "geomint-core-demo: unknown argument '" << argv[i] << "'\n";
    std::cerr << "usage: geomint-core-demo\n  prints nodes, Lagrange bases and D1/D2 weights for m = 2..6\n";
    return std::strcmp(argv[i], "--help") == 0 ? 0 : 2;
  }
  print_all(std::make_integer_sequence<int, 5>{});
  return 0;
}
