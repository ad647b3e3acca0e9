#pragma once
/// Symmetric compositions of a symmetric second-order method (Stormer-Verlet) of order 6, 8 and
/// 10, with coefficients refined to the full precision of the scalar by Newton's method on the
/// order conditions. geomint uses them as peers in work-precision comparisons.
///
/// A composition Psi_h = S_{gamma_s h} o ... o S_{gamma_1 h} of a symmetric basic method S_h with
/// gamma_i = gamma_{s+1-i}. The published coefficients (26 digits) are the start values:
/// - order 6, 7 stages: Yoshida, H. (1990), Construction of higher order symplectic
///   integrators, Phys. Lett. A 150, 262-268 (solution A);
/// - order 8, 17 stages: Kahan, W., Li, R.-C. (1997), Composition constants for raising the
///   orders of unconventional schemes for ordinary differential equations, Math. Comp. 66,
///   1089-1099 (method s17odr8a);
/// - order 10, 35 stages: Sofroniou, M., Spaletta, G. (2005), Derivation of symmetric
///   composition constants for symmetric integrators, Optim. Methods Softw. 20, 597-613.
///
/// Order conditions (independent of the basic method): a symmetric S_h is the exact flow of a
/// modified field, S_h = exp(h Y_1 + h^3 Y_3 + h^5 Y_5 + ...) with arbitrary non-commuting
/// Y_k (only odd powers by symmetry). Psi_h has order p iff
///   prod_i exp(gamma_i h Y_1 + gamma_i^3 h^3 Y_3 + ...) = exp(h Y_1) + O(h^(p+1))
/// in the free associative algebra on the Y_k, Y_k of degree k. The coefficient of a word
/// Y_{k_1}...Y_{k_r} in exp(sum_k gamma^k Y_k) is gamma^(k_1+...+k_r) / r!, so both sides are
/// polynomials in the gamma_i, compared word by word up to degree p (many conditions are
/// redundant; they are consistent, and Gauss-Newton with a minimum-norm step solves them).

#include <array>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>

#include "geomint/ad/dual.hpp"
#include "geomint/core/multiprecision.hpp"

namespace geomint::analysis {

namespace detail {

/// The words of degree <= p over the letters Y_1, Y_3, ..., Y_p (letter Y_k has degree k), and
/// for each word its splits into prefix and suffix: what multiplying by one factor needs.
class word_table {
 public:
  explicit word_table(int p) {
    std::vector<std::vector<int>> words{{}};
    for (std::size_t i = 0; i < words.size(); ++i) {
      int deg = 0;
      for (int k : words[i]) deg += k;
      for (int k = 1; deg + k <= p; k += 2) {
        std::vector<int> w = words[i];
        w.push_back(k);
        words.push_back(w);
      }
    }
    std::map<std::vector<int>, int> index;
    for (std::size_t i = 0; i < words.size(); ++i) index[words[i]] = static_cast<int>(i);
    splits_.resize(words.size());
    target_one_letter_.assign(words.size(), -1);
    for (std::size_t i = 0; i < words.size(); ++i) {
      const auto& w = words[i];
      for (std::size_t cut = 0; cut <= w.size(); ++cut) {
        const std::vector<int> prefix(w.begin(), w.begin() + static_cast<long>(cut));
        int deg = 0;
        for (std::size_t j = cut; j < w.size(); ++j) deg += w[j];
        splits_[i].push_back({index.at(prefix), deg, static_cast<int>(w.size() - cut)});
      }
      bool only_y1 = true;
      for (int k : w) only_y1 = only_y1 && k == 1;
      if (only_y1) target_one_letter_[i] = static_cast<int>(w.size());
    }
  }
  struct split {
    int prefix;      ///< index of the prefix word
    int suffix_deg;  ///< degree of the suffix
    int suffix_len;  ///< number of letters of the suffix
  };
  std::size_t size() const { return splits_.size(); }
  const std::vector<split>& splits(std::size_t w) const { return splits_[w]; }
  /// r if the word is Y_1^r (its coefficient in exp(h Y_1) is 1/r!), else -1.
  int y1_power(std::size_t w) const { return target_one_letter_[w]; }

 private:
  std::vector<std::vector<split>> splits_;
  std::vector<int> target_one_letter_;
};

/// Coefficients of prod_i exp(sum_k gamma_i^k Y_k) minus those of exp(Y_1), word by word, for
/// a scalar S (T, or a dual number for the Jacobian).
template <class S>
std::vector<S> order_residual(const word_table& words, const std::vector<S>& gamma, int p) {
  std::vector<S> inv_fact(static_cast<std::size_t>(p) + 1);
  inv_fact[0] = S(1);
  for (int r = 1; r <= p; ++r) inv_fact[static_cast<std::size_t>(r)] = inv_fact[static_cast<std::size_t>(r - 1)] / S(r);
  std::vector<S> prod(words.size(), S(0)), next(words.size());
  prod[0] = S(1);  // the empty word
  std::vector<S> power(static_cast<std::size_t>(p) + 1);
  for (const S& g : gamma) {
    power[0] = S(1);
    for (int k = 1; k <= p; ++k) power[static_cast<std::size_t>(k)] = power[static_cast<std::size_t>(k - 1)] * g;
    for (std::size_t w = 0; w < words.size(); ++w) {
      S sum(0);
      for (const auto& s : words.splits(w))
        sum += prod[static_cast<std::size_t>(s.prefix)] * (power[static_cast<std::size_t>(s.suffix_deg)] *
                                                           inv_fact[static_cast<std::size_t>(s.suffix_len)]);
      next[w] = sum;
    }
    prod.swap(next);
  }
  for (std::size_t w = 0; w < words.size(); ++w)
    if (const int r = words.y1_power(w); r >= 0) prod[w] -= inv_fact[static_cast<std::size_t>(r)];
  return prod;
}

}  // namespace detail

/// One of the three published symmetric compositions; the coefficients are the published
/// values refined by Newton in T until the order conditions hold to T's precision.
template <class T>
class symmetric_composition {
 public:
  static constexpr int max_unknowns = 18;

  static symmetric_composition yoshida6() {
    return symmetric_composition("yoshida-s7-order6", 6, 7,
                                 {"0.78451361047755726381949763", "0.23557321335935813368479318",
                                  "-1.17767998417887100694641568", "1.31518632068391121888424973"});
  }
  static symmetric_composition kahan_li8() {
    return symmetric_composition(
        "kahan-li-s17-order8", 8, 17,
        {"0.13020248308889008087881763", "0.56116298177510838456196441", "-0.38947496264484728640807860",
         "0.15884190655515560089621075", "-0.39590389413323757733623154", "0.18453964097831570709183254",
         "0.25837438768632204729397911", "0.29501172360931029887096624", "-0.60550853383003451169892108"});
  }
  static symmetric_composition sofroniou_spaletta10() {
    return symmetric_composition(
        "sofroniou-spaletta-s35-order10", 10, 35,
        {"0.07879572252168641926390768", "0.31309610341510852776481247", "0.02791838323507806610952027",
         "-0.22959284159390709415121340", "0.13096206107716486317465686", "-0.26973340565451071434460973",
         "0.07497334315589143566613711", "0.11199342399981020488957508", "0.36613344954622675119314812",
         "-0.39910563013603589787862981", "0.10308739852747107731580277", "0.41143087395589023782070412",
         "-0.00486636058313526176219566", "-0.39203335370863990644808194", "0.05194250296244964703718290",
         "0.05066509075992449633587434", "0.04967437063972987905456880", "0.04931773575959453791768001"});
  }

  const std::string& name() const { return name_; }
  int order() const { return order_; }
  int stages() const { return static_cast<int>(gamma_.size()); }
  /// gamma_1..gamma_s (symmetric).
  const std::vector<T>& gamma() const { return gamma_; }
  /// Newton iterations used by the refinement.
  int newton_iterations() const { return iterations_; }

  /// max over the words of degree <= order of |coefficient of the composition - of exp(Y_1)|.
  T order_defect() const { return defect_of(gamma_); }
  /// The same for the conditions of one order more (nonzero: the order is exactly order()).
  T next_order_defect() const {
    const detail::word_table words(order_ + 2);
    T worst(0);
    for (const T& r : detail::order_residual(words, gamma_, order_ + 2)) {
      using std::abs;
      if (abs(r) > worst) worst = abs(r);
    }
    return worst;
  }

 private:
  template <class>
  friend class symmetric_composition;

  symmetric_composition(std::string name, int order, int stages, std::vector<const char*> start)
      : name_(std::move(name)), order_(order) {
    if constexpr (double_expansion<T>::value) {
      // A sum of doubles (libqd's types) cannot be constructed from an Eigen::Index, as Eigen's
      // decompositions do: refined in 100 digits and rounded term by term to T.
      const symmetric_composition<boost::multiprecision::cpp_bin_float_100> wide(name_, order, stages, start);
      for (const auto& g : wide.gamma_) gamma_.push_back(narrow<T>(g));
      iterations_ = wide.iterations_;
    } else {
      const int half = (stages + 1) / 2;
      if (static_cast<int>(start.size()) != half || half > max_unknowns)
        throw std::logic_error("geomint::symmetric_composition: wrong number of start values");
      std::vector<T> x(static_cast<std::size_t>(half));
      for (int i = 0; i < half; ++i) x[static_cast<std::size_t>(i)] = from_decimal<T>(start[static_cast<std::size_t>(i)]);
      refine(x, stages);
      gamma_ = expand(x, stages);
    }
  }

  template <class S>
  static std::vector<S> expand(const std::vector<S>& half, int stages) {
    std::vector<S> g(static_cast<std::size_t>(stages));
    for (int i = 0; i < stages; ++i) {
      const int j = i < (stages + 1) / 2 ? i : stages - 1 - i;
      g[static_cast<std::size_t>(i)] = half[static_cast<std::size_t>(j)];
    }
    return g;
  }

  T defect_of(const std::vector<T>& g) const {
    const detail::word_table words(order_);
    T worst(0);
    for (const T& r : detail::order_residual(words, g, order_)) {
      using std::abs;
      if (abs(r) > worst) worst = abs(r);
    }
    return worst;
  }

  /// Gauss-Newton with the minimum-norm step (complete orthogonal decomposition): the
  /// conditions are redundant, and for s17 and s35 the solution set has free directions; the
  /// minimum-norm step stays next to the published point.
  void refine(std::vector<T>& x, int stages) {
    using D = geomint::dual<T, max_unknowns>;
    using std::abs;
    const detail::word_table words(order_);
    const int K = static_cast<int>(x.size());
    const T tol = T(64) * std::numeric_limits<T>::epsilon();
    T previous = std::numeric_limits<T>::infinity();
    for (iterations_ = 0; iterations_ < 40; ++iterations_) {
      std::vector<D> xd(x.size());
      for (int k = 0; k < K; ++k) xd[static_cast<std::size_t>(k)] = D::variable(x[static_cast<std::size_t>(k)], k);
      const std::vector<D> r = detail::order_residual(words, expand(xd, stages), order_);
      Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> J(static_cast<Eigen::Index>(r.size()), K);
      Eigen::Matrix<T, Eigen::Dynamic, 1> F(static_cast<Eigen::Index>(r.size()));
      T worst(0);
      for (std::size_t w = 0; w < r.size(); ++w) {
        F(static_cast<Eigen::Index>(w)) = r[w].v;
        if (abs(r[w].v) > worst) worst = abs(r[w].v);
        for (int k = 0; k < K; ++k) J(static_cast<Eigen::Index>(w), k) = r[w].d[static_cast<std::size_t>(k)];
      }
      // Stop once at round-off level and no longer improving.
      if (worst <= tol && !(worst < previous / T(2))) break;
      previous = worst;
      Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>> cod(J);
      cod.setThreshold(T(1024) * std::numeric_limits<T>::epsilon());
      const Eigen::Matrix<T, Eigen::Dynamic, 1> dx = cod.solve(F);
      for (int k = 0; k < K; ++k) x[static_cast<std::size_t>(k)] -= dx(k);
    }
    if (!(defect_of(expand(x, stages)) <= tol))
      throw std::runtime_error("geomint::symmetric_composition: Newton did not reach the order conditions");
  }

  std::string name_;
  int order_;
  std::vector<T> gamma_;
  int iterations_ = 0;
};

/// One step of the composition of Stormer-Verlet (kick-drift-kick) for qddot = force(q), unit
/// mass: stage i kicks p by gamma_i h/2 force, drifts q by gamma_i h p, kicks again; adjacent
/// half kicks share one force evaluation, and `f` carries force(q) from step to step (FSAL),
/// so a step costs `stages` force evaluations. `f` must hold force(q) on entry.
template <class T, class V, class Force>
void composition_step(const std::vector<T>& gamma, V& q, V& p, V& f, const T& h, const Force& force) {
  const std::size_t n = static_cast<std::size_t>(q.size());
  for (std::size_t i = 0; i < gamma.size(); ++i) {
    const T half = gamma[i] * h / T(2), full = gamma[i] * h;
    for (std::size_t j = 0; j < n; ++j) p[j] += half * f[j];
    for (std::size_t j = 0; j < n; ++j) q[j] += full * p[j];
    force(q, f);
    for (std::size_t j = 0; j < n; ++j) p[j] += half * f[j];
  }
}

}  // namespace geomint::analysis
