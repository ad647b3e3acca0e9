#pragma once
/// One-step methods as data: the Butcher tableaux of the classes of methods, over any
/// coefficient type K (geomint::rational and big_rational at compile time, exact_rational and
/// field_element of methods/number_field.hpp at run time, or a floating scalar), with S stages.
///
/// - `rk`      (c, A, b)                 for y' = f(y);
/// - `prk`     (c, A, b, Ahat, bhat)     for q' = f(q, p), p' = g(q, p) (A, b for q; Ahat, bhat for p);
/// - `rkn`     (c, A, bbar, b)           for q'' = f(q);
/// - `nystrom` (c, A, Ap, bbar, b)       for q'' = F(q, q'):
///     Q_i = q + c_i h v + h^2 sum_j a_ij F_j,  V_i = v + h sum_j ap_ij F_j,  F_i = F(Q_i, V_i),
///     q1 = q + h v + h^2 sum_j bbar_j F_j,   v1 = v + h sum_j b_j F_j
/// (Hairer, Norsett & Wanner, Solving ODEs I, sections II.1, II.14 and II.15; docs/references.md).
///
/// The types are aggregates of std::array, so over geomint::rational they are structural and
/// constexpr. Build them with make_rk, make_prk, make_rkn and make_nystrom, which take braced
/// lists and check every length at compile time (a short list is a static_assert, never a
/// silent zero):
///
///   constexpr auto verlet = geomint::methods::make_rkn<geomint::rational>(
///       {0, 1}, {{0, 0}, {geomint::rational(1, 2), 0}}, {geomint::rational(1, 2), 0},
///       {geomint::rational(1, 2), geomint::rational(1, 2)});

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace geomint::methods {

/// The class of a method.
enum class method_kind { rk, prk, rkn, nystrom };

inline std::string_view to_string(method_kind k) {
  switch (k) {
    case method_kind::rk: return "rk";
    case method_kind::prk: return "prk";
    case method_kind::rkn: return "rkn";
    case method_kind::nystrom: return "nystrom";
  }
  return "?";
}

template <class K, int S>
using stage_vector = std::array<K, static_cast<std::size_t>(S)>;
template <class K, int S>
using stage_matrix = std::array<std::array<K, static_cast<std::size_t>(S)>, static_cast<std::size_t>(S)>;

template <class K, int S>
struct rk {
  static_assert(S >= 1, "geomint::methods::rk: a method has at least one stage");
  static constexpr method_kind kind = method_kind::rk;
  static constexpr int stages = S;
  using coefficient = K;
  stage_vector<K, S> c{};
  stage_matrix<K, S> a{};
  stage_vector<K, S> b{};
};

template <class K, int S>
struct prk {
  static_assert(S >= 1, "geomint::methods::prk: a method has at least one stage");
  static constexpr method_kind kind = method_kind::prk;
  static constexpr int stages = S;
  using coefficient = K;
  stage_vector<K, S> c{};
  stage_matrix<K, S> a{};
  stage_vector<K, S> b{};
  stage_matrix<K, S> ahat{};
  stage_vector<K, S> bhat{};
};

template <class K, int S>
struct rkn {
  static_assert(S >= 1, "geomint::methods::rkn: a method has at least one stage");
  static constexpr method_kind kind = method_kind::rkn;
  static constexpr int stages = S;
  using coefficient = K;
  stage_vector<K, S> c{};
  stage_matrix<K, S> a{};
  stage_vector<K, S> bbar{};
  stage_vector<K, S> b{};
};

template <class K, int S>
struct nystrom {
  static_assert(S >= 1, "geomint::methods::nystrom: a method has at least one stage");
  static constexpr method_kind kind = method_kind::nystrom;
  static constexpr int stages = S;
  using coefficient = K;
  stage_vector<K, S> c{};
  stage_matrix<K, S> a{};
  stage_matrix<K, S> ap{};
  stage_vector<K, S> bbar{};
  stage_vector<K, S> b{};
};

namespace detail {
template <class K, std::size_t S>
constexpr std::array<K, S> vector_of(const K (&x)[S]) {
  std::array<K, S> out{};
  for (std::size_t i = 0; i < S; ++i) out[i] = x[i];
  return out;
}
template <class K, std::size_t S>
constexpr std::array<std::array<K, S>, S> matrix_of(const K (&x)[S][S]) {
  std::array<std::array<K, S>, S> out{};
  for (std::size_t i = 0; i < S; ++i)
    for (std::size_t j = 0; j < S; ++j) out[i][j] = x[i][j];
  return out;
}
}  // namespace detail

/// rk from braced lists: c (S entries) fixes S; A must be S x S and b have S entries.
template <class K, std::size_t S, std::size_t R, std::size_t C, std::size_t B>
constexpr rk<K, static_cast<int>(S)> make_rk(const K (&c)[S], const K (&a)[R][C], const K (&b)[B]) {
  static_assert(R == S && C == S, "geomint::methods::make_rk: a must have S rows of S entries (S = the number of entries of c)");
  static_assert(B == S, "geomint::methods::make_rk: b must have S entries (S = the number of entries of c)");
  return {detail::vector_of(c), detail::matrix_of(a), detail::vector_of(b)};
}

/// prk from braced lists: c fixes S; A and Ahat S x S, b and bhat S entries.
template <class K, std::size_t S, std::size_t R, std::size_t C, std::size_t B, std::size_t RH, std::size_t CH, std::size_t BH>
constexpr prk<K, static_cast<int>(S)> make_prk(const K (&c)[S], const K (&a)[R][C], const K (&b)[B], const K (&ahat)[RH][CH],
                                               const K (&bhat)[BH]) {
  static_assert(R == S && C == S, "geomint::methods::make_prk: a must have S rows of S entries (S = the number of entries of c)");
  static_assert(B == S, "geomint::methods::make_prk: b must have S entries (S = the number of entries of c)");
  static_assert(RH == S && CH == S,
                "geomint::methods::make_prk: ahat must have S rows of S entries (S = the number of entries of c)");
  static_assert(BH == S, "geomint::methods::make_prk: bhat must have S entries (S = the number of entries of c)");
  return {detail::vector_of(c), detail::matrix_of(a), detail::vector_of(b), detail::matrix_of(ahat), detail::vector_of(bhat)};
}

/// rkn from braced lists: c fixes S; A S x S, bbar and b S entries.
template <class K, std::size_t S, std::size_t R, std::size_t C, std::size_t BB, std::size_t B>
constexpr rkn<K, static_cast<int>(S)> make_rkn(const K (&c)[S], const K (&a)[R][C], const K (&bbar)[BB], const K (&b)[B]) {
  static_assert(R == S && C == S, "geomint::methods::make_rkn: a must have S rows of S entries (S = the number of entries of c)");
  static_assert(BB == S, "geomint::methods::make_rkn: bbar must have S entries (S = the number of entries of c)");
  static_assert(B == S, "geomint::methods::make_rkn: b must have S entries (S = the number of entries of c)");
  return {detail::vector_of(c), detail::matrix_of(a), detail::vector_of(bbar), detail::vector_of(b)};
}

/// nystrom from braced lists: c fixes S; A and Ap S x S, bbar and b S entries.
template <class K, std::size_t S, std::size_t R, std::size_t C, std::size_t RP, std::size_t CP, std::size_t BB, std::size_t B>
constexpr nystrom<K, static_cast<int>(S)> make_nystrom(const K (&c)[S], const K (&a)[R][C], const K (&ap)[RP][CP],
                                                       const K (&bbar)[BB], const K (&b)[B]) {
  static_assert(R == S && C == S,
                "geomint::methods::make_nystrom: a must have S rows of S entries (S = the number of entries of c)");
  static_assert(RP == S && CP == S,
                "geomint::methods::make_nystrom: ap must have S rows of S entries (S = the number of entries of c)");
  static_assert(BB == S, "geomint::methods::make_nystrom: bbar must have S entries (S = the number of entries of c)");
  static_assert(B == S, "geomint::methods::make_nystrom: b must have S entries (S = the number of entries of c)");
  return {detail::vector_of(c), detail::matrix_of(a), detail::matrix_of(ap), detail::vector_of(bbar), detail::vector_of(b)};
}

/// Whether A is strictly lower triangular (exact comparison with zero).
template <class K, int S>
constexpr bool strictly_lower(const stage_matrix<K, S>& a) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i)
    for (std::size_t j = i; j < static_cast<std::size_t>(S); ++j)
      if (!(a[i][j] == K(0))) return false;
  return true;
}

/// A tableau of any kind with its stage count known at run time (a tableau file, a
/// conversion): the arrays the kind uses, the others empty.
template <class K>
struct tableau_data {
  method_kind kind = method_kind::rkn;
  int stages = 0;
  std::string name;
  std::vector<K> c, b, bbar, bhat;
  std::vector<std::vector<K>> a, ap, ahat;
};

namespace detail {
template <class K, int S>
constexpr std::vector<K> to_vector(const stage_vector<K, S>& x) {
  return std::vector<K>(x.begin(), x.end());
}
template <class K, int S>
constexpr std::vector<std::vector<K>> to_vector(const stage_matrix<K, S>& x) {
  std::vector<std::vector<K>> out;
  for (const auto& row : x) out.emplace_back(row.begin(), row.end());
  return out;
}
}  // namespace detail

/// The run-time form of a tableau of any kind.
template <class K, int S>
tableau_data<K> data_of(const rk<K, S>& t) {
  tableau_data<K> d;
  d.kind = method_kind::rk;
  d.stages = S;
  d.c = detail::to_vector<K, S>(t.c);
  d.a = detail::to_vector<K, S>(t.a);
  d.b = detail::to_vector<K, S>(t.b);
  return d;
}
template <class K, int S>
tableau_data<K> data_of(const prk<K, S>& t) {
  tableau_data<K> d;
  d.kind = method_kind::prk;
  d.stages = S;
  d.c = detail::to_vector<K, S>(t.c);
  d.a = detail::to_vector<K, S>(t.a);
  d.b = detail::to_vector<K, S>(t.b);
  d.ahat = detail::to_vector<K, S>(t.ahat);
  d.bhat = detail::to_vector<K, S>(t.bhat);
  return d;
}
template <class K, int S>
tableau_data<K> data_of(const rkn<K, S>& t) {
  tableau_data<K> d;
  d.kind = method_kind::rkn;
  d.stages = S;
  d.c = detail::to_vector<K, S>(t.c);
  d.a = detail::to_vector<K, S>(t.a);
  d.bbar = detail::to_vector<K, S>(t.bbar);
  d.b = detail::to_vector<K, S>(t.b);
  return d;
}
template <class K, int S>
tableau_data<K> data_of(const nystrom<K, S>& t) {
  tableau_data<K> d;
  d.kind = method_kind::nystrom;
  d.stages = S;
  d.c = detail::to_vector<K, S>(t.c);
  d.a = detail::to_vector<K, S>(t.a);
  d.ap = detail::to_vector<K, S>(t.ap);
  d.bbar = detail::to_vector<K, S>(t.bbar);
  d.b = detail::to_vector<K, S>(t.b);
  return d;
}
template <class K>
const tableau_data<K>& data_of(const tableau_data<K>& t) {
  return t;
}

/// The fixed-size rkn (c, a, bbar, b) of a run-time form with S stages: a tableau_data of kind
/// rkn or nystrom, or a nystrom_form (methods/nystrom_form.hpp), whose RKN part it is (Ap, used
/// only off natural systems, is dropped). std::invalid_argument for another number of stages.
template <int S, class Form>
rkn<typename decltype(Form::c)::value_type, S> rkn_of(const Form& f) {
  if (f.stages != S || f.c.size() != static_cast<std::size_t>(S) || f.a.size() != static_cast<std::size_t>(S) ||
      f.bbar.size() != static_cast<std::size_t>(S) || f.b.size() != static_cast<std::size_t>(S))
    throw std::invalid_argument("geomint::methods::rkn_of<" + std::to_string(S) + ">: the tableau has " +
                                std::to_string(f.stages) + " stages, or lacks c, a, bbar or b");
  rkn<typename decltype(Form::c)::value_type, S> t;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    t.c[i] = f.c[i];
    t.bbar[i] = f.bbar[i];
    t.b[i] = f.b[i];
    if (f.a[i].size() != static_cast<std::size_t>(S))
      throw std::invalid_argument("geomint::methods::rkn_of<" + std::to_string(S) + ">: row " + std::to_string(i + 1) +
                                  " of a has another length");
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) t.a[i][j] = f.a[i][j];
  }
  return t;
}

}  // namespace geomint::methods
