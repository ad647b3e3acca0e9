#pragma once
/// The irreducible form of a tableau of any kind (methods/tableau.hpp), over an exact K.
///
/// A method is reducible when fewer stages give the same step on every problem (Hairer &
/// Wanner, Solving ODEs II, section IV.12; Hundsdorfer & Spijker 1981):
/// - DJ-reducible (Dahlquist & Jeltsch 1979): a set of stages that neither the update nor any
///   other stage uses (zero weights, zero columns outside the set) can be dropped;
/// - S-reducible (Stetter 1973): a partition of the stages such that, within a class, the rows
///   of every stage matrix have equal sums over each class (and, for rkn and nystrom, equal
///   nodes c, which enter the stages directly): the stages of a class are equal, so they merge
///   into one with the class's summed weights and the rows' class sums as coefficients.
/// `irreducible_form` drops and merges until neither applies (the coarsest equitable partition,
/// by refinement). Symplecticity conditions such as b_i a_ij + b_j a_ji = b_i b_j are
/// necessary only for irreducible methods: Lobatto IIIB with s = 2 violates them and is the
/// implicit midpoint rule, which satisfies them.
///
/// The stage matrices are A (rk), A and Ahat (prk; one partition for both), A (rkn), A and Ap
/// (nystrom); the weights b (rk), b and bhat (prk), bbar and b (rkn, nystrom). For rk and prk
/// (autonomous systems, where the step uses A 1) stages merge whatever their published c; a
/// merged class keeps its c where its stages agree, else takes the row sum of the merged A.

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// A tableau's irreducible method and where each of its stages went.
template <class K>
struct irreducible_method {
  tableau_data<K> method;     ///< the irreducible tableau (same kind)
  std::vector<int> stage_of;  ///< the stage of `method` that stage i became; -1 if it was dropped
};

namespace detail {

template <class K>
using stage_rows = std::vector<std::vector<K>>;

/// The stage matrices of a kind: A, and Ahat (prk) or Ap (nystrom).
template <class K>
std::vector<stage_rows<K>*> stage_matrices_of(tableau_data<K>& t) {
  std::vector<stage_rows<K>*> out{&t.a};
  if (t.kind == method_kind::prk) out.push_back(&t.ahat);
  if (t.kind == method_kind::nystrom) out.push_back(&t.ap);
  return out;
}

/// The weight vectors of a kind: b (rk), b and bhat (prk), bbar and b (rkn, nystrom).
template <class K>
std::vector<std::vector<K>*> stage_weights_of(tableau_data<K>& t) {
  if (t.kind == method_kind::rk) return {&t.b};
  if (t.kind == method_kind::prk) return {&t.b, &t.bhat};
  return {&t.bbar, &t.b};
}

template <class K>
void check_reducible_input(tableau_data<K>& t) {
  const auto s = static_cast<std::size_t>(t.stages);
  auto bad = [&](std::size_t n) { return n != s; };
  bool wrong = t.stages < 1 || bad(t.c.size());
  for (const stage_rows<K>* m : stage_matrices_of(t)) {
    wrong = wrong || bad(m->size());
    for (const auto& row : *m) wrong = wrong || bad(row.size());
  }
  for (const std::vector<K>* w : stage_weights_of(t)) wrong = wrong || bad(w->size());
  if (wrong) throw std::invalid_argument("geomint::methods::irreducible_form: the arrays do not have the tableau's stage count");
}

/// The stages `keep` of t (in order), each as the sum of the stages mapped to it: class_of[i]
/// is the new stage of stage i (-1: dropped), `classes` the number of new stages.
template <class K>
tableau_data<K> merged(tableau_data<K>& t, const std::vector<int>& class_of, int classes) {
  const auto s = static_cast<std::size_t>(t.stages), r = static_cast<std::size_t>(classes);
  std::vector<int> first(r, -1);
  for (std::size_t i = 0; i < s; ++i)
    if (class_of[i] >= 0 && first[static_cast<std::size_t>(class_of[i])] < 0) first[static_cast<std::size_t>(class_of[i])] = static_cast<int>(i);
  tableau_data<K> out;
  out.kind = t.kind;
  out.stages = classes;
  out.name = t.name;
  auto matrices_in = stage_matrices_of(t);
  auto matrices_out = stage_matrices_of(out);
  for (std::size_t m = 0; m < matrices_in.size(); ++m) {
    stage_rows<K>& to = *matrices_out[m];
    to.assign(r, std::vector<K>(r, K(0)));
    for (std::size_t l = 0; l < r; ++l) {
      const auto& row = (*matrices_in[m])[static_cast<std::size_t>(first[l])];
      for (std::size_t j = 0; j < s; ++j)
        if (class_of[j] >= 0) to[l][static_cast<std::size_t>(class_of[j])] = to[l][static_cast<std::size_t>(class_of[j])] + row[j];
    }
  }
  auto weights_in = stage_weights_of(t);
  auto weights_out = stage_weights_of(out);
  for (std::size_t w = 0; w < weights_in.size(); ++w) {
    weights_out[w]->assign(r, K(0));
    for (std::size_t i = 0; i < s; ++i)
      if (class_of[i] >= 0) (*weights_out[w])[static_cast<std::size_t>(class_of[i])] = (*weights_out[w])[static_cast<std::size_t>(class_of[i])] + (*weights_in[w])[i];
  }
  out.c.assign(r, K(0));
  for (std::size_t l = 0; l < r; ++l) {
    const K& c = t.c[static_cast<std::size_t>(first[l])];
    bool agree = true;
    for (std::size_t i = 0; i < s; ++i)
      if (class_of[i] == static_cast<int>(l) && !(t.c[i] == c)) agree = false;
    if (agree) {
      out.c[l] = c;
    } else {  // rk, prk only (rkn and nystrom classes have equal c): the node the step uses
      for (std::size_t j = 0; j < r; ++j) out.c[l] = out.c[l] + out.a[l][j];
    }
  }
  return out;
}

/// DJ-reduction: class_of[i] = -1 for the stages nothing uses; the count of those kept.
template <class K>
int dj_classes(tableau_data<K>& t, std::vector<int>& class_of) {
  const auto s = static_cast<std::size_t>(t.stages);
  std::vector<bool> used(s, false);
  std::vector<std::size_t> todo;
  for (const std::vector<K>* w : stage_weights_of(t))
    for (std::size_t i = 0; i < s; ++i)
      if (!((*w)[i] == K(0)) && !used[i]) {
        used[i] = true;
        todo.push_back(i);
      }
  const auto matrices = stage_matrices_of(t);
  while (!todo.empty()) {
    const std::size_t i = todo.back();
    todo.pop_back();
    for (const stage_rows<K>* m : matrices)
      for (std::size_t j = 0; j < s; ++j)
        if (!used[j] && !((*m)[i][j] == K(0))) {
          used[j] = true;
          todo.push_back(j);
        }
  }
  class_of.assign(s, -1);
  int kept = 0;
  for (std::size_t i = 0; i < s; ++i)
    if (used[i]) class_of[i] = kept++;
  return kept;
}

/// S-reduction: the coarsest partition, finer than equal c for rkn and nystrom, in which stages
/// of one class have equal row sums over every class in every stage matrix; the class count.
template <class K>
int s_classes(tableau_data<K>& t, std::vector<int>& class_of) {
  const auto s = static_cast<std::size_t>(t.stages);
  const bool nodes_matter = t.kind == method_kind::rkn || t.kind == method_kind::nystrom;
  const auto matrices = stage_matrices_of(t);
  class_of.assign(s, 0);
  int classes = 1;
  if (nodes_matter) {
    classes = 0;
    for (std::size_t i = 0; i < s; ++i) {
      class_of[i] = -1;
      for (std::size_t k = 0; k < i && class_of[i] < 0; ++k)
        if (t.c[k] == t.c[i]) class_of[i] = class_of[k];
      if (class_of[i] < 0) class_of[i] = classes++;
    }
  }
  for (;;) {
    // sums[i][m * classes + l] = sum over j in class l of matrix m's entry (i, j)
    std::vector<std::vector<K>> sums(s, std::vector<K>(matrices.size() * static_cast<std::size_t>(classes), K(0)));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t m = 0; m < matrices.size(); ++m)
        for (std::size_t j = 0; j < s; ++j) {
          K& x = sums[i][m * static_cast<std::size_t>(classes) + static_cast<std::size_t>(class_of[j])];
          x = x + (*matrices[m])[i][j];
        }
    std::vector<int> refined(s, -1);
    int count = 0;
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t k = 0; k < i && refined[i] < 0; ++k) {
        if (class_of[k] != class_of[i]) continue;
        bool same = true;
        for (std::size_t x = 0; x < sums[i].size() && same; ++x) same = sums[i][x] == sums[k][x];
        if (same) refined[i] = refined[k];
      }
      if (refined[i] < 0) refined[i] = count++;
    }
    class_of = refined;
    if (count == classes) return count;
    classes = count;
  }
}

}  // namespace detail

/// The irreducible method of `t` (see the top of the file); std::invalid_argument for arrays
/// that do not have the stage count. Needs an exact K (equality decides the classes). A method
/// whose weights all vanish has no stage left: its step is y1 = y0 (rk, prk) or the free drift
/// q1 = q + h v (rkn, nystrom).
template <class K>
irreducible_method<K> irreducible_form(const tableau_data<K>& t) {
  irreducible_method<K> out{t, {}};
  detail::check_reducible_input(out.method);
  out.stage_of.resize(static_cast<std::size_t>(t.stages));
  for (int i = 0; i < t.stages; ++i) out.stage_of[static_cast<std::size_t>(i)] = i;
  auto apply = [&](const std::vector<int>& class_of, int classes) {
    for (int& k : out.stage_of)
      if (k >= 0) k = class_of[static_cast<std::size_t>(k)];
    out.method = detail::merged(out.method, class_of, classes);
  };
  for (;;) {
    std::vector<int> class_of;
    const int kept = detail::dj_classes(out.method, class_of);
    if (kept < out.method.stages) apply(class_of, kept);
    const int classes = detail::s_classes(out.method, class_of);
    if (classes == out.method.stages) return out;
    apply(class_of, classes);  // then DJ again: merged weights may cancel
  }
}

}  // namespace geomint::methods
