#pragma once
/// The front end `modified` (geomint-modified) over a system_list: the modified equation of a
/// method, exactly, and its prediction of the energy error checked against the integrator
/// (include/geomint/analysis/bseries/: modified_equation.hpp, modified_hamiltonian.hpp,
/// rkn_series.hpp, energy_prediction.hpp).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/analysis/bseries/energy_prediction.hpp"
#include "geomint/analysis/bseries/exact_series.hpp"
#include "geomint/analysis/bseries/lagrangian_field.hpp"
#include "geomint/analysis/bseries/lagrangian_hamiltonian.hpp"
#include "geomint/analysis/bseries/method_analysis.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/modified_hamiltonian.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/methods/coefficients.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "geomint/cli/progress.hpp"
#include "geomint/cli/study.hpp"

namespace geomint::cli {

namespace modified_detail {

using namespace geomint::analysis::bseries;
using methods::exact_rational;
using methods::field_element;

/// The usage text of the front end called `program` over the systems `systems`.
inline std::string modified_usage(const std::string& program, const std::vector<std::string>& systems) {
  const std::string indent(program.size() + 8, ' ');
  return "usage: " + program + " (--scheme S [--nodes F] [--m M] | --tableau FILE) [--order K]\n" + indent +
         "[--system S [--q0 a[,b]] [--p0 a[,b]] --tau T[,T2,...] --steps N\n" + indent +
         " [--terms K] [--digits 16|50|100] [--csv] [--no-monitor]]\n" +
         std::string(
    "The modified equation y' = f + h^p f_{p+1} + ... of a method (backward error analysis;\n"
    "Hairer, Lubich & Wanner, Geometric Numerical Integration, 2006, chapter IX), exactly.\n"
    "  --scheme S    a library scheme by its exact RKN tableau: lpf (--nodes, --m 2..8), galerkin\n"
    "                (--m 1..8), midpoint, trapezoidal; P-series on the Nystrom trees\n"
    "  --tableau F   a tableau file (docs/guide/tableau_files.md): rk on one-colour trees (B-series),\n"
    "                prk on two-colour trees, rkn and nystrom on their Nystrom trees\n"
    "  --order K     print the coefficients b(t) of the modified field per tree up to order K (the\n"
    "                h^(|t|-1) term is sum b(t)/sigma(t) F(t)), exact; for a symplectic method\n"
    "                also the modified Hamiltonian's terms h^(|t|-1) c H(t) per free tree (rk: every\n"
    "                H; scheme, rkn, nystrom: H = |p|^2/2 + V(q); prk: H = T(p) + V(q)).\n"
    "                Trees: q/p (two colours) or y (one colour) with the children in brackets.\n"
    "                K at most 16 (scheme, rkn), 10 (nystrom; prk, and the modified Hamiltonian of\n"
    "                two colours), 14 (rk).\n"
    "With --system S (any number of degrees of freedom) it runs the method (the\n"
    "scheme's stepper or the tableau's) N steps at each tau and predicts its energy\n"
    "error from the modified field, evaluated along the numerical solution with the system's\n"
    "derivatives by automatic differentiation:\n"
    "  symplectic:   H(y_n) - H(y_0) = -sum_{j=1..K} h^(p+j-1) (H_{p+j}(y_n) - H_{p+j}(y_0)), the\n"
    "                differences of H_j by Gauss quadrature of omega(f_j, dy) along each step (an\n"
    "                error estimate by a lower rule above 1/1000 of the prediction fails the row);\n"
    "                CSV tau,steps,predicted_max_energy_error,measured_max_energy_error (max over n\n"
    "                of |predicted| and of |H(y_n) - H(y_0)|)\n"
    "  otherwise:    the drift rate of H: predicted = mean over the run of\n"
    "                sum_j h^(p+j-1) grad H . f_{p+j}(y_n); measured = least-squares slope of\n"
    "                H(y_n) - H(y_0) in t; CSV tau,steps,predicted_drift_rate,measured_drift_rate\n"
    "                (the h^p term can average to zero over a period: RK4 drifts at h^5, --terms 2)\n"
    "  not natural:  a Lagrangian that is not natural (lpf; rk and nystrom tableaux): the step is a\n"
    "                Nystrom method in y = (q, v) for q'' = F(q, q') (Legendre maps at both ends), so\n"
    "                E(y_n) - E(y_0) (E = v . L_v - L = H) is predicted as the integral over [0, t_n]\n"
    "                of sum_j h^(p+j-1) grad E . f_{p+j}(y); CSV and maxima as for symplectic.\n"
    "                galerkin and midpoint there are the Gauss RK method on H(q, p) = p . v - L:\n"
    "                symplectic, in (q, p); trapezoidal has no prediction there\n"
    "  --terms K     the terms f_{p+1}..f_{p+K} (default 1); the coefficients (--order, --terms,\n"
    "                with or without --system) reach order 16 for a scheme and rkn, 10 for nystrom\n"
    "                and for lpf on a Lagrangian that is not natural, 10 for prk (all two-colour\n"
    "                trees), 14 for rk and for galerkin and midpoint on a Lagrangian that is not\n"
    "                natural\n"
    "  --digits D    working precision 16 (default), 50 or 100\n"
    "Initial data as geomint-run (--p0 the momentum); the step monitor is on (--no-monitor turns it\n"
    "off; docs/guide/robustness.md). A failed run prints nan.\n"
    "Exit 2 on usage errors, 3 on a failed run.\n") +
         "systems: " + comma_list(systems) + "\n";
}


using namespace geomint::analysis::bseries;
using methods::exact_rational;
using methods::field_element;


struct options {
  std::string program;
  std::string scheme, tableau, system;
  std::string nodes = "equispaced";
  int m = 2;
  bool nodes_given = false, m_given = false, csv = false, monitor = true;
  int order = 0, terms = 1, digits = 16;
  long steps = 0;
  std::vector<std::string> tau, q0, p0;
};

/// A method as the exact series data of its modified field.
struct method_series {
  std::string label;
  int order = 0;             ///< p
  bool symplectic = false;
  /// A Lagrangian that is not natural: the prediction is the accumulated E(y_n) - E(y_0) of the
  /// method's Nystrom form in (q, v) (lagrangian_series_of).
  bool accumulated = false;
  std::string symplecticity_basis;
  bool one_colour = false;   ///< an rk tableau (B-series); else P-series
  /// Two colours: the Hamiltonians the modified Hamiltonian is printed for (natural for a
  /// scheme, rkn and nystrom; separable for prk) and the colour of q' = H_p on the trees.
  hamiltonian_class hamiltonians = hamiltonian_class::natural;
  int position_colour = 0;
  tree_set trees{1, 1};
  std::vector<bool> wanted;  ///< the trees whose coefficients the method defines
  std::vector<field_element> b;
};

/// The scheme's spec (tools/common/stepper.hpp) and its exact RKN tableau.
inline scheme_spec spec_of(const options& o) {
  scheme_spec s;
  s.scheme = o.scheme;
  s.nodes = o.nodes;
  s.m = o.m;
  return s;
}
inline exact_rkn_tableau exact_tableau_of(const options& o) {
  if (o.scheme == "midpoint") return midpoint_tableau();
  if (o.scheme == "trapezoidal") return trapezoidal_tableau();
  if (o.scheme == "galerkin") return with_int<1, max_exact_stages>(o.m, []<int M>() { return galerkin_tableau<M>(); });
  return with_int<2, max_exact_m>(
      o.m, [&]<int M>() { return with_node_family(o.nodes, []<class Family>() { return lpf_tableau<M, Family>(); }); });
}

/// The largest tree order the series needs: K of --order, p + --terms with --system (the
/// prediction evaluates F(t) of the trees to order p + K; every tree the generators accept has
/// its derivatives evaluated, elementary_differentials.hpp). Each kind of method checks it
/// against its tree class's cap.
inline int needed_order(const options& o, int p) { return std::max(o.order, o.system.empty() ? 0 : p + o.terms); }

inline method_series series_of(const options& o) {
  method_series m;
  std::vector<field_element> a;
  if (!o.scheme.empty()) {
    const exact_rkn_tableau t = exact_tableau_of(o);
    m.label = o.scheme + (o.scheme == "lpf" ? " --nodes " + o.nodes : std::string()) +
              (o.scheme == "lpf" || o.scheme == "galerkin" ? " --m " + std::to_string(o.m) : std::string());
    m.order = tree_order(t);
    m.symplectic = symplecticity(t).symplectic;
    m.symplecticity_basis = "RKN conditions (exact)";
    const int n = needed_order(o, m.order);
    if (n > max_tree_order_rkn)
      throw cli::usage_error("--order/--terms: trees of order " + std::to_string(n) + " needed, at most " +
                             std::to_string(max_tree_order_rkn) + " for a scheme (order " + std::to_string(m.order) + ")");
    m.trees = tree_set(std::max(n, 1), tree_class::rkn);
    m.wanted.assign(static_cast<std::size_t>(m.trees.size()), true);
    for (const exact_rational& x : elementary_weights(m.trees, t)) a.emplace_back(x);
  } else {
    methods::tableau_data<field_element> t;
    try {
      t = methods::read_tableau_file(o.tableau);
    } catch (const methods::tableau_file_error& e) {
      throw cli::usage_error(std::string("--tableau: ") + e.what());
    }
    m.label = (t.name.empty() ? o.tableau : t.name) + " (" + std::string(methods::to_string(t.kind)) + ", " +
              std::to_string(t.stages) + " stages)";
    const method_analysis verdict = analyse_method(t);
    m.order = verdict.order;
    m.symplectic = verdict.symplectic;
    m.symplecticity_basis = verdict.symplecticity_basis;
    m.one_colour = t.kind == methods::method_kind::rk;
    if (t.kind == methods::method_kind::prk) {  // the pair's first tableau on p (colour 0)
      m.hamiltonians = hamiltonian_class::separable;
      m.position_colour = 1;
    }
    const int n = needed_order(o, m.order);
    const tree_class kind = t.kind == methods::method_kind::rkn       ? tree_class::rkn
                            : t.kind == methods::method_kind::nystrom ? tree_class::nystrom
                                                                      : tree_class::all;
    const int limit = m.one_colour                ? max_tree_order_one_colour
                      : kind == tree_class::rkn     ? max_tree_order_rkn
                      : kind == tree_class::nystrom ? max_tree_order_nystrom
                                                    : max_tree_order_two_colours;
    if (verdict.order_is_lower_bound && !o.system.empty())
      throw cli::usage_error("--tableau: the order is at least " + std::to_string(m.order) + " (all conditions analysed hold): "
                             "no leading term within the trees analysed");
    if (n > limit)
      throw cli::usage_error("--order/--terms: trees of order " + std::to_string(n) + " needed, at most " +
                             std::to_string(limit) + " for this tableau (order " + std::to_string(m.order) + ")");
    m.trees = m.one_colour ? tree_set(std::max(n, 1), 1) : tree_set(std::max(n, 1), kind);
    m.wanted.assign(static_cast<std::size_t>(m.trees.size()), true);
    m.b = exact_series_of(m.trees, partitioned_form_of(t), &m.wanted).b;
    return m;
  }
  m.b = exact_modified_field(m.trees, a);
  return m;
}

/// The series of the method on a Lagrangian that is not natural, where the step is a Nystrom
/// method in (q, v) for q'' = F(q, q') composed with the Legendre maps p <-> v at both ends, so
/// H(q_n, p_n) = E(q_n, v_n) (docs/results/schemes.md, "LPF as a Nystrom method"): lpf by its
/// collocation Nystrom weights on the Nystrom trees of F(q, q') (rkn_series.hpp); an rk or
/// nystrom tableau as series_of has it (its stepper runs that Nystrom form in (q, v),
/// methods/tableau_method.hpp). The method is not symplectic there in general
/// (docs/results/schemes.md, item 5), so the prediction is the accumulated energy error.
/// galerkin (degree m, m-point Gauss quadrature) and midpoint (its m = 1) step (q, p) as the
/// Gauss collocation RK method on H(q, p) = p . v - L (HLW, Geometric Numerical Integration,
/// 2006, Theorem VI.6.4: Ahat = A for Gauss quadrature; the same B-series on every colouring,
/// so the one-colour trees, collocation_rk_weights): symplectic, predicted in (q, p) with the
/// field of lagrangian_hamiltonian.hpp. trapezoidal (Lobatto quadrature) is outside the
/// theorem: usage_error naming why.
inline method_series lagrangian_series_of(const options& o, method_series m, const std::string& system) {
  const std::string here = " on --system " + system + " (a Lagrangian that is not natural)";
  if (o.scheme == "trapezoidal")
    throw cli::usage_error("--scheme trapezoidal" + here + ": no prediction: its two-point Lobatto quadrature is outside "
                           "the Galerkin theorem (Hairer, Lubich & Wanner 2006, Theorem VI.6.4), which makes a variational "
                           "integrator a partitioned RK method in (q, p): the path of degree 1 has equal velocities at both "
                           "stages, while Lobatto IIIB forces equal stage momenta; galerkin and midpoint have a prediction");
  if (o.scheme == "galerkin" || o.scheme == "midpoint") {
    const int stages = o.scheme == "midpoint" ? 1 : o.m;
    m.one_colour = true;
    const int n = needed_order(o, m.order);
    if (n > max_tree_order_one_colour)
      throw cli::usage_error("--order/--terms: trees of order " + std::to_string(n) + " needed, at most " +
                             std::to_string(max_tree_order_one_colour) + " for --scheme " + o.scheme + here);
    m.trees = tree_set(std::max(n, 1), 1);
    m.wanted.assign(static_cast<std::size_t>(m.trees.size()), true);
    std::vector<field_element> a;
    for (const exact_rational& x : with_int<1, max_exact_stages>(stages, [&]<int M>() {
           return collocation_rk_weights(m.trees, galerkin_tableau<M>());
         }))
      a.emplace_back(x);
    m.b = exact_modified_field(m.trees, a);
    m.symplectic = true;
    m.symplecticity_basis = "Gauss RK method on H(q, p)";
    return m;
  }
  if (!o.tableau.empty()) {
    const methods::method_kind kind = methods::read_tableau_file(o.tableau).kind;
    if (kind == methods::method_kind::rkn || kind == methods::method_kind::prk)
      throw cli::usage_error("--tableau: " + std::string(methods::to_string(kind)) + " tableaux run on natural systems only, not" +
                             here + "; rk and nystrom tableaux run on any Lagrangian");
  } else {
    const int n = m.trees.max_order();
    if (n > max_tree_order_nystrom)
      throw cli::usage_error("--order/--terms: trees of order " + std::to_string(n) + " needed, at most " +
                             std::to_string(max_tree_order_nystrom) + here);
    m.trees = tree_set(n, tree_class::nystrom);
    m.wanted.assign(static_cast<std::size_t>(m.trees.size()), true);
    std::vector<field_element> a;
    for (const exact_rational& x : collocation_nystrom_weights(m.trees, exact_tableau_of(o))) a.emplace_back(x);
    m.b = exact_modified_field(m.trees, a);
  }
  m.symplectic = false;
  m.accumulated = true;
  m.symplecticity_basis = "Nystrom form in (q, v)";
  return m;
}

/// A tree as text: its root's letter (y; or q, p for colours 0, 1) and its children in brackets.
inline std::string tree_text(const tree_set& trees, int t) {
  const rooted_tree& r = trees[t];
  std::string s = trees.colours() == 1 ? "y" : (r.colour == 0 ? "q" : "p");
  if (r.subtrees.empty()) return s;
  s += '[';
  for (std::size_t i = 0; i < r.subtrees.size(); ++i) s += (i ? "," : "") + tree_text(trees, r.subtrees[i]);
  return s + ']';
}

/// An exact coefficient as text: a rational, or a polynomial in the field's generator r.
inline std::string exact_text(const field_element& x) {
  if (x.is_rational()) return x.rational_value().str();
  std::string s;
  const auto& c = x.coefficients();
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k] == 0) continue;
    s += (s.empty() ? "" : " + ") + std::string("(") + c[k].str() + ")" + (k ? (k == 1 ? "*r" : "*r^" + std::to_string(k)) : "");
  }
  return s;
}

inline void print_series(const method_series& m, int order, bool csv) {
  if (csv) {
    std::cout << "order,tree,sigma,b\n";
  } else {
    std::cout << m.label << ": order " << m.order << ", " << (m.symplectic ? "symplectic" : "not symplectic") << " ("
              << m.symplecticity_basis << ")\n"
              << "modified field: h f~ = sum_t h^|t| b(t)/sigma(t) F(t)\n";
  }
  for (int t = 0; t < m.trees.first(order + 1); ++t) {
    const auto i = static_cast<std::size_t>(t);
    if (!m.wanted[i]) continue;
    if (csv)
      std::cout << m.trees[t].order << ',' << tree_text(m.trees, t) << ',' << m.trees[t].sigma << ',' << exact_text(m.b[i]) << '\n';
    else
      std::cout << "  |t| = " << m.trees[t].order << "  " << std::left << std::setw(28) << tree_text(m.trees, t) << std::right
                << " sigma " << std::setw(3) << m.trees[t].sigma << "  b = " << exact_text(m.b[i]) << '\n';
  }
  if (csv || !m.symplectic) return;
  std::cout << "modified Hamiltonian: H~ = sum over free trees h^(|t|-1) c H(t), H(y[t1..tm]) = H^(m+1)(F(t1),..,F(tm))";
  if (!m.one_colour)
    std::cout << (m.hamiltonians == hamiltonian_class::natural ? " on H = |p|^2/2 + V(q)" : " on H = T(p) + V(q)")
              << ", the derivatives of H in q or p by the subtrees' root colours";
  std::cout << '\n';
  if (!m.one_colour && order > max_tree_order_two_colours) {
    std::cout << "  (printed to order " << max_tree_order_two_colours << " only: the free trees need all two-colour trees)\n";
    order = max_tree_order_two_colours;
  }
  const tree_set trees(order, m.one_colour ? 1 : 2);
  // b on the full set: a class set's trees carried over (the others' elementary differentials
  // vanish on the class of Hamiltonians, hamiltonian_trees leaves them out).
  std::vector<field_element> b(static_cast<std::size_t>(trees.size()), field_element(0));
  const std::vector<int> same = m.trees.kind() == tree_class::all ? std::vector<int>{} : indices_in(m.trees, trees);
  for (int t = 0; t < m.trees.first(order + 1); ++t)
    b[static_cast<std::size_t>(same.empty() ? t : same[static_cast<std::size_t>(t)])] = m.b[static_cast<std::size_t>(t)];
  std::vector<bool> marked;  // two colours: the trees whose H(t) can be non-zero on the class
  if (!m.one_colour) marked = hamiltonian_trees(trees, m.hamiltonians, m.position_colour);
  for (const auto& term : modified_hamiltonian(trees, b, m.one_colour ? nullptr : &marked))
    std::cout << "  h^" << term.order - 1 << "  " << std::left << std::setw(28) << tree_text(trees, term.tree) << std::right
              << " c = " << exact_text(term.coefficient) << '\n';
}

template <class T>
std::string sci(const T& v) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(6) << v;
  return out.str();
}

/// One row: the run at one tau and its prediction (symplectic: maxima; otherwise drift rates).
template <class T>
struct row {
  T predicted{0}, measured{0}, quadrature{0};
  std::string failure;
};

/// Least-squares slope of e in t.
template <class T>
T slope(const std::vector<T>& t, const std::vector<T>& e) {
  T mt(0), me(0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    mt += t[i];
    me += e[i];
  }
  mt /= T(static_cast<long>(t.size()));
  me /= T(static_cast<long>(t.size()));
  T sxy(0), sxx(0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    sxy += (t[i] - mt) * (e[i] - me);
    sxx += (t[i] - mt) * (t[i] - mt);
  }
  return sxy / sxx;
}

/// One run at `tau`; its steps advance `bar` from `done` on (the progress line of a terminal).
template <class Sys, class T, class List>
row<T> run_case(List list, const options& o, const method_series& m, const T& tau, progress& bar, std::size_t done) {
  row<T> r;
  constexpr int n = Sys::dof;
  const auto stepper = o.scheme.empty()
                           ? make_tableau_stepper<T>(list, o.system,
                                                     methods::to_scalar<T>(methods::nystrom_form_of(methods::read_tableau_file(o.tableau))))
                           : make_stepper<T>(list, o.system, spec_of(o));
  if (o.monitor) stepper->set_monitor(step_monitor<T>::on());
  dynamic_vector<T> q, p, q1, p1;
  try {
    std::tie(q, p) = default_initial_state<T>(list, o.system, *stepper, o.q0, o.p0,
                                                     [](const std::string& s) { return parse_number<T>("--q0/--p0", s); });
  } catch (const std::invalid_argument& e) {
    throw cli::usage_error(e.what());
  }
  const T h0 = stepper->energy(q, p);
  using state = vec<T, 2 * n>;
  std::vector<state> ys;
  std::vector<T> times, errors;
  for (long k = 0;; ++k) {
    state y;
    if (!m.accumulated) {
      y << q, p;
    } else {  // (q, v): v by the inverse Legendre map
      vec<T, n> v;
      if (!lagrangian_derivatives<Sys, T>::velocity(Sys{}, vec<T, n>(q), vec<T, n>(p), v)) {
        r.failure = "step " + std::to_string(k) + ": the inverse Legendre map p -> v did not converge";
        return r;
      }
      y << q, v;
    }
    ys.push_back(y);
    times.push_back(T(k) * tau);
    errors.push_back(T(stepper->energy(q, p) - h0));
    if (k == o.steps) break;
    if (k % 1024 == 0) bar.set(done + static_cast<std::size_t>(k));  // (a terminal only)
    const step_status st = stepper->try_step(q, p, tau, q1, p1);
    if (!st) {
      r.failure = "step " + std::to_string(k) + " failed: " + st.message();
      return r;
    }
    q = q1;
    p = p1;
  }
  const modified_terms<T> terms =
      make_modified_terms<T>(m.trees, m.b, m.wanted, m.order, o.terms, methods::coefficient_converter<T>{});
  using std::abs;
  const auto take_maxima = [&](const std::vector<T>& predicted) {
    for (std::size_t k = 0; k < ys.size(); ++k) {
      r.predicted = std::max(r.predicted, T(abs(predicted[k])));
      r.measured = std::max(r.measured, T(abs(errors[k])));
    }
  };
  const auto symplectic_prediction = [&](const auto& field) {
    const auto prediction = predict_energy_error(terms, field, ys, tau);
    take_maxima(prediction.error);
    r.quadrature = prediction.quadrature_estimate;
    if (!(r.quadrature <= r.predicted / 1000))
      r.failure = "the quadrature's error estimate " + sci(r.quadrature) + " is above 1/1000 of the prediction";
  };
  // The fields of a Lagrangian that is not natural throw std::domain_error where L_vv is singular
  // or the inverse Legendre map does not converge at a point the prediction needs: a failed row.
  try {
    if constexpr (!natural_system<Sys>) {
      if (m.symplectic) {
        symplectic_prediction(hamiltonian_field<lagrangian_hamiltonian<Sys>, n>{});
      } else {
        const lagrangian_field<Sys> field{};
        take_maxima(predict_energy_change(terms, field, ys, tau, [&](const state& y) { return field.energy_gradient(y); }));
      }
    } else if (m.symplectic) {
      symplectic_prediction(natural_field<Sys, T>{});
    } else {
      const std::vector<T> rate = predict_energy_rate(terms, natural_field<Sys, T>{}, ys, tau);
      for (const T& x : rate) r.predicted += x;
      r.predicted /= T(static_cast<long>(rate.size()));
      r.measured = slope(times, errors);
    }
  } catch (const std::domain_error& e) {
    r.failure = std::string("the prediction failed: ") + e.what();
  }
  return r;
}

/// The series the prediction on --system uses: the method's own on a natural system, else
/// lagrangian_series_of; --order prints this one too.
template <class List>
method_series series_on_system(List list, const options& o, const method_series& natural_series) {
  return with_system(list, o.system, [&]<class Sys>() -> method_series {
    return natural_system<Sys> ? natural_series : lagrangian_series_of(o, natural_series, o.system);
  });
}

template <class T, class List>
int run(List list, const options& o, const method_series& m) {
  return with_system(list, o.system, [&]<class Sys>() -> int {
    if (!o.scheme.empty()) {
      try {
        check_scheme<T>(list, o.system, spec_of(o));
      } catch (const std::invalid_argument& e) {
        throw cli::usage_error(e.what());
      }
    }
    for (const auto& [flag, values] : {std::pair{"--q0", &o.q0}, std::pair{"--p0", &o.p0}}) {
      if (!values->empty() && values->size() != static_cast<std::size_t>(Sys::dof))
        throw cli::usage_error(std::string(flag) + " needs " + std::to_string(Sys::dof) + " value(s) for --system " + o.system);
      for (const std::string& s : *values) parse_number<T>(flag, s);
    }
    int status = 0;
    const char* header = m.symplectic || m.accumulated ? "tau,steps,predicted_max_energy_error,measured_max_energy_error"
                                                       : "tau,steps,predicted_drift_rate,measured_drift_rate";
    if (o.csv) std::cout << header << '\n';
    else
      std::cout << m.label << " on " << o.system << " (order " << m.order << ", "
                << (m.symplectic ? "symplectic: max |H - H0|"
                                 : m.accumulated ? "Nystrom form in (q, v): max |E - E0|" : "not symplectic: dH/dt")
                << ", " << o.terms
                << " term(s), " << o.digits << " digits)\n"
                << std::setw(12) << "tau" << std::setw(10) << "steps" << std::setw(16) << "predicted" << std::setw(16)
                << "measured" << std::setw(12) << "ratio" << '\n';
    // The steps of every tau, counted by the progress line; the messages of the runs are held
    // until it is erased.
    progress bar(o.program, o.tau.size() * static_cast<std::size_t>(o.steps), "steps");
    std::ostringstream messages;
    std::size_t done = 0;
    for (const std::string& text : o.tau) {
      const T tau = parse_number<T>("--tau", text);
      const row<T> r = run_case<Sys, T>(list, o, m, tau, bar, done);
      done += static_cast<std::size_t>(o.steps);
      if (!r.failure.empty()) {
        messages << o.program << ": tau = " << text << ": " << r.failure << '\n';
        status = cli::exit_run_failure;
      }
      // A failed run is no measurement: its row says nan.
      const bool ok = r.failure.empty();
      const std::string predicted = ok ? sci(r.predicted) : "nan", measured = ok ? sci(r.measured) : "nan";
      if (o.csv) {
        std::cout << text << ',' << o.steps << ',' << predicted << ',' << measured << '\n';
      } else {
        std::ostringstream ratio;
        ratio << std::fixed << std::setprecision(6) << static_cast<double>(r.predicted / r.measured);
        std::cout << std::setw(12) << text << std::setw(10) << o.steps << std::setw(16) << predicted << std::setw(16) << measured
                  << std::setw(12) << (ok ? ratio.str() : "nan") << '\n';
      }
      if (m.symplectic)
        messages << o.program << ": tau = " << text << ": quadrature error estimate " << sci(r.quadrature) << '\n';
    }
    bar.finish();
    std::cerr << messages.str();
    return status;
  });
}

}  // namespace modified_detail

/// The program geomint-modified over the systems of `list` (its usage text: modified_usage).
template <class List>
int modified_main(List list, int argc, const char* const* argv, study_tool tool = {}) {
  using namespace modified_detail;
  if (tool.program.empty()) tool.program = "geomint-modified";
  options o;
  o.program = tool.program;
  parser cl(tool.program, tool.usage.empty() ? modified_usage(tool.program, system_names(list)) : tool.usage);
  cl.value("--scheme", [&](const std::string& v) {
      o.scheme = cli::parse_choice("--scheme", v, exact_scheme_names());
    })
      .value("--nodes", [&](const std::string& v) {
        o.nodes = cli::parse_node_family("--nodes", v);
        o.nodes_given = true;
      })
      .value("--m", [&](const std::string& v) {
        o.m = cli::parse_integer<int>("--m", v, 1, 8);
        o.m_given = true;
      })
      .value("--tableau", [&](const std::string& v) { o.tableau = v; })
      .value("--order", [&](const std::string& v) { o.order = cli::parse_integer<int>("--order", v, 1, max_tree_order_rkn); })
      .value("--system", [&](const std::string& v) { o.system = cli::parse_choice("--system", v, system_names(list)); })
      .value("--q0", [&](const std::string& v) { o.q0 = cli::parse_real_list("--q0", v, cli::real_bound::finite); })
      .value("--p0", [&](const std::string& v) { o.p0 = cli::parse_real_list("--p0", v, cli::real_bound::finite); })
      .value("--tau", [&](const std::string& v) { o.tau = cli::parse_real_list("--tau", v, cli::real_bound::positive); })
      .value("--steps", [&](const std::string& v) { o.steps = cli::parse_integer<long>("--steps", v, 1, 1'000'000L); })
      .value("--terms", [&](const std::string& v) { o.terms = cli::parse_integer<int>("--terms", v, 1, max_tree_order_rkn - 1); })
      .value("--digits", [&](const std::string& v) { o.digits = std::stoi(cli::parse_choice("--digits", v, {"16", "50", "100"})); })
      .toggle("--csv", [&] { o.csv = true; })
      .toggle("--no-monitor", [&] { o.monitor = false; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  try {
    if (o.scheme.empty() == o.tableau.empty()) throw cli::usage_error("give one of --scheme and --tableau");
    if (!o.tableau.empty() && (o.nodes_given || o.m_given)) throw cli::usage_error("--nodes and --m apply to --scheme, not to --tableau");
    const scheme_entry* entry = find_scheme(o.scheme);  // null with --tableau
    if (o.nodes_given && !(entry && entry->has_nodes))
      throw cli::usage_error("--nodes applies to --scheme " +
                             schemes_with_nodes(true) + " only");
    if (o.m_given && entry && !entry->has_m)
      throw cli::usage_error("--m applies to --scheme " +
                             schemes_with_m(true) + " only");
    if (o.scheme == "lpf" && o.m < 2) throw cli::usage_error("--m must be in 2..8 for --scheme lpf");
    if (o.system.empty()) {
      if (o.order == 0) throw cli::usage_error("--order K is needed without --system");
      const std::pair<const char*, bool> given[] = {{"--tau", !o.tau.empty()}, {"--steps", o.steps > 0}, {"--q0", !o.q0.empty()},
                                                    {"--p0", !o.p0.empty()}, {"--terms", o.terms != 1}};
      for (const auto& [flag, is_given] : given)
        if (is_given) throw cli::usage_error(std::string(flag) + " applies with --system only");
    } else {
      if (o.tau.empty()) throw cli::usage_error("--tau is needed with --system");
      if (o.steps == 0) throw cli::usage_error("--steps is needed with --system");
      if (o.order > 0 && o.csv) throw cli::usage_error("--order with --system --csv would mix two tables: run them apart");
    }
    method_series m = series_of(o);
    if (!o.system.empty()) m = series_on_system(list, o, m);
    if (o.order > 0) print_series(m, o.order, o.csv);
    int status = 0;
    if (!o.system.empty()) {
      if (o.digits == 16) status = run<double>(list, o, m);
      else if (o.digits == 50) status = run<boost::multiprecision::cpp_bin_float_50>(list, o, m);
      else status = run<boost::multiprecision::cpp_bin_float_100>(list, o, m);
    }
    return finish_stdout(tool.program, status);
  } catch (const cli::usage_error& e) {
    return finish_stdout(tool.program, cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cerr << tool.program << ": " << e.what() << '\n';
    return finish_stdout(tool.program, 1);
  }
}

}  // namespace geomint::cli
