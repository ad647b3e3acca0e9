#pragma once
/// Exact Runge-Kutta-Nystrom tableaux of the library's schemes, at compile time.
///
/// For a natural system (L = 1/2 qdot^T M qdot - V(q), constant M; unit mass below, f = -grad V)
/// one step of every scheme of the library is an s-stage RKN method
///   Q_i = q + c_i tau p + tau^2 sum_j a_ij f(Q_j),
///   q1  = q + tau p + tau^2 sum_j bbar_j f(Q_j),   p1 = p + tau sum_j b_j f(Q_j):
/// - LPF of degree m on a node family (Kong & Yang 2020, eq. 10-12): the collocation RKN method
///   on the s = m - 1 interior nodes. With lt_j the Lagrange basis on the interior nodes,
///   a_ij = int_0^{c_i} (c_i - u) lt_j(u) du, bbar_j = int_0^1 (1 - u) lt_j(u) du,
///   b_j = int_0^1 lt_j(u) du (the path's second derivative, of degree m - 2, interpolates the
///   force at the interior nodes; eq. 12 and the momentum match, eq. 9-11).
/// - Galerkin VI of degree m with m-point Gauss quadrature: the partitioned RK method
///   a_ij = int_0^{c_i} l_j, ahat_ij = b_j (1 - a_ji / b_i) (Hairer, Lubich, Wanner, Geometric
///   Numerical Integration, 2nd ed., Theorem VI.6.4), which for Gauss nodes is the Gauss
///   collocation RK method; as an RKN method a = A Ahat = A^2, bbar = b^T A.
/// - Midpoint VI (scheme 17): s = 1, c = 1/2, a = 1/4, bbar = 1/2, b = 1.
/// - Trapezoidal VI: Stormer-Verlet, s = 2, c = (0, 1), a = [[0, 0], [1/2, 0]], bbar = (1/2, 0),
///   b = (1/2, 1/2).
///
/// The headers, one job each: the exact tableau over its stage algebra Q[x]/(N)
/// (analysis/stage_algebra.hpp); the node polynomials N (analysis/node_polynomial.hpp, from
/// core/orthogonal_polynomials.hpp); the builders of the collocation tableaux
/// (analysis/collocation_tableaux.hpp) and of explicit rational ones
/// (analysis/rational_rkn_tableau.hpp); the numeric tableau in a scalar type
/// (analysis/numeric_tableau.hpp).

#include "geomint/analysis/collocation_tableaux.hpp"
#include "geomint/analysis/node_polynomial.hpp"
#include "geomint/analysis/numeric_tableau.hpp"
#include "geomint/analysis/rational_rkn_tableau.hpp"
#include "geomint/analysis/stage_algebra.hpp"
