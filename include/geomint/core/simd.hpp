#pragma once
/// double_pack<W>: W doubles in one SIMD register (GCC/Clang vector extensions), a scalar type
/// for natural systems' forces, so that the fixed-point engine (schemes/gauss_fixed_point.hpp)
/// evaluates W stage forces of a sweep in one call, as IRKGL16-SIMD does (Antonana, Makazaga &
/// Murua 2020, docs/references.md). Lane-wise + - * /, sqrt (the hardware's, correctly rounded,
/// as std::sqrt), and sin, cos, exp, log: with GEOMINT_HAVE_SLEEF (link libsleef, Debian
/// libsleef-dev) SLEEF's vector functions of 1-ulp accuracy (Shibata & Petrogalli, IEEE TPDS 31,
/// 2020), else std:: per lane (the same values as the scalar code).
///
/// A natural system opts in with `static constexpr bool stage_parallel_forces = true;` when its
/// `potential_gradient<S>` uses only what this type has (arithmetic with S and its own
/// constants read as S, geomint's sine, cosine, inverse_sqrt, and sin, cos, sqrt, exp, log found
/// by argument-dependent lookup): C++ cannot detect that a template body compiles for a type,
/// so the engine never tries it unasked. `simd_width` is the pack the engine uses: 4 with AVX, 2
/// otherwise; GEOMINT_SIMD_WIDTH overrides it (8 with AVX-512F, not the default: on the
/// project's AMD EPYC 8 lanes were slower than 4 on the outer solar system, whose 512-bit
/// divisions and square roots that processor executes in halves).

#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(GEOMINT_HAVE_SLEEF)
#include <sleef.h>
#endif

namespace geomint {
/// The pack and its functions live in geomint::simd, where argument-dependent lookup finds them
/// (`using std::sin; sin(x)`), and no unqualified sin(double) in geomint sees them.
namespace simd {

#if defined(GEOMINT_SIMD_WIDTH)
inline constexpr int simd_width = GEOMINT_SIMD_WIDTH;
#elif defined(__AVX__)
inline constexpr int simd_width = 4;
#else
inline constexpr int simd_width = 2;
#endif
/// The lanes of an ensemble (geomint/ensemble.hpp, one trajectory per lane): the widest register,
/// 8 with AVX-512, else simd_width (the stage packs' 4 with AVX-512 is the stage forces' choice).
#if defined(GEOMINT_SIMD_WIDTH)
inline constexpr int ensemble_width = GEOMINT_SIMD_WIDTH;
#elif defined(__AVX512F__)
inline constexpr int ensemble_width = 8;
#else
inline constexpr int ensemble_width = simd_width;
#endif

namespace detail {
/// The vector-extension type of W doubles (GCC takes no dependent vector_size in a template),
/// aligned as a double: Eigen aligns its fixed-size storage by its own rule, below what a
/// 32-byte vector would require (Clang refuses that), and unaligned vector loads cost nothing
/// more on current processors.
template <int W>
struct register_of;
typedef double register2 __attribute__((vector_size(16), aligned(8)));
typedef double register4 __attribute__((vector_size(32), aligned(8)));
typedef double register8 __attribute__((vector_size(64), aligned(8)));
template <>
struct register_of<2> { using type = register2; };
template <>
struct register_of<4> { using type = register4; };
template <>
struct register_of<8> { using type = register8; };
}  // namespace detail

template <int W>
struct double_pack {
  static_assert(W == 2 || W == 4 || W == 8, "geomint::double_pack<W>: W must be 2, 4 or 8 lanes");
  using register_type = typename detail::register_of<W>::type;
  register_type v;

  double_pack() : v{} {}
  /// Every lane x (a constant of a potential, read as S).
  double_pack(double x) : v(x - register_type{}) {}  // NOLINT: implicit, as a scalar's
  explicit double_pack(const register_type& r) : v(r) {}

  /// W consecutive doubles from p (no alignment needed) and back.
  static double_pack load(const double* p) {
    double_pack out;
    __builtin_memcpy(&out.v, p, sizeof(out.v));
    return out;
  }
  void store(double* p) const { __builtin_memcpy(p, &v, sizeof(v)); }

  double operator[](int lane) const { return v[lane]; }
  void set(int lane, double x) { v[lane] = x; }

  double_pack& operator+=(const double_pack& o) { v += o.v; return *this; }
  double_pack& operator-=(const double_pack& o) { v -= o.v; return *this; }
  double_pack& operator*=(const double_pack& o) { v *= o.v; return *this; }
  double_pack& operator/=(const double_pack& o) { v /= o.v; return *this; }
  friend double_pack operator+(const double_pack& a, const double_pack& b) { return double_pack(a.v + b.v); }
  friend double_pack operator-(const double_pack& a, const double_pack& b) { return double_pack(a.v - b.v); }
  friend double_pack operator*(const double_pack& a, const double_pack& b) { return double_pack(a.v * b.v); }
  friend double_pack operator/(const double_pack& a, const double_pack& b) { return double_pack(a.v / b.v); }
  friend double_pack operator-(const double_pack& a) { return double_pack(-a.v); }
  friend double_pack operator+(const double_pack& a) { return a; }
};

namespace detail {
/// f applied to each lane (the fallback, and the functions SLEEF is not asked for).
template <int W, class F>
double_pack<W> per_lane(const double_pack<W>& x, F f) {
  double_pack<W> out;
  for (int i = 0; i < W; ++i) out.set(i, f(x[i]));
  return out;
}
}  // namespace detail

/// SLEEF's function of the pack's width where the target has it (the d4 functions need AVX, the
/// d8 ones AVX-512F), else f per lane.
#if defined(GEOMINT_HAVE_SLEEF) && defined(__SSE2__)
#define GEOMINT_SLEEF_CALL2(sleef2) \
  if constexpr (W == 2) return double_pack<W>((R)(sleef2((__m128d)(x.v))));
#else
#define GEOMINT_SLEEF_CALL2(sleef2)
#endif
#if defined(GEOMINT_HAVE_SLEEF) && defined(__AVX__)
#define GEOMINT_SLEEF_CALL4(sleef4) \
  if constexpr (W == 4) return double_pack<W>((R)(sleef4((__m256d)(x.v))));
#else
#define GEOMINT_SLEEF_CALL4(sleef4)
#endif
#if defined(GEOMINT_HAVE_SLEEF) && defined(__AVX512F__)
#define GEOMINT_SLEEF_CALL8(sleef8) \
  if constexpr (W == 8) return double_pack<W>((R)(sleef8((__m512d)(x.v))));
#else
#define GEOMINT_SLEEF_CALL8(sleef8)
#endif
#define GEOMINT_SLEEF_PACK_FUNCTION(name, sleef2, sleef4, sleef8)                \
  template <int W>                                                               \
  double_pack<W> name(const double_pack<W>& x) {                                 \
    using R [[maybe_unused]] = typename double_pack<W>::register_type;           \
    GEOMINT_SLEEF_CALL2(sleef2)                                                  \
    GEOMINT_SLEEF_CALL4(sleef4)                                                  \
    GEOMINT_SLEEF_CALL8(sleef8)                                                  \
    return detail::per_lane(x, [](double y) { return std::name(y); });           \
  }

/// sin, cos, exp, log of every lane (SLEEF's 1-ulp functions where built with it).
GEOMINT_SLEEF_PACK_FUNCTION(sin, Sleef_sind2_u10, Sleef_sind4_u10, Sleef_sind8_u10)
GEOMINT_SLEEF_PACK_FUNCTION(cos, Sleef_cosd2_u10, Sleef_cosd4_u10, Sleef_cosd8_u10)
GEOMINT_SLEEF_PACK_FUNCTION(exp, Sleef_expd2_u10, Sleef_expd4_u10, Sleef_expd8_u10)
GEOMINT_SLEEF_PACK_FUNCTION(log, Sleef_logd2_u10, Sleef_logd4_u10, Sleef_logd8_u10)
#undef GEOMINT_SLEEF_PACK_FUNCTION
#undef GEOMINT_SLEEF_CALL2
#undef GEOMINT_SLEEF_CALL4
#undef GEOMINT_SLEEF_CALL8

/// sqrt of every lane: the loop becomes the vector square-root instruction where the target has
/// one (correctly rounded, as std::sqrt).
template <int W>
double_pack<W> sqrt(const double_pack<W>& x) {
  double_pack<W> out;
  for (int i = 0; i < W; ++i) out.v[i] = __builtin_sqrt(x.v[i]);
  return out;
}

/// a b + c of every lane with one rounding (as std::fma): the FMA instruction where the target
/// has it, else std::fma per lane.
template <int W>
double_pack<W> fma(const double_pack<W>& a, const double_pack<W>& b, const double_pack<W>& c) {
  using R [[maybe_unused]] = typename double_pack<W>::register_type;
#if defined(__FMA__)
  if constexpr (W == 2) return double_pack<W>((R)_mm_fmadd_pd((__m128d)a.v, (__m128d)b.v, (__m128d)c.v));
  if constexpr (W == 4) return double_pack<W>((R)_mm256_fmadd_pd((__m256d)a.v, (__m256d)b.v, (__m256d)c.v));
#endif
#if defined(__AVX512F__)
  if constexpr (W == 8) return double_pack<W>((R)_mm512_fmadd_pd((__m512d)a.v, (__m512d)b.v, (__m512d)c.v));
#endif
  double_pack<W> out;
  for (int i = 0; i < W; ++i) out.set(i, std::fma(a[i], b[i], c[i]));
  return out;
}

/// |x| of every lane (as std::fabs): the sign bits cleared, one vector AND.
template <int W>
double_pack<W> abs(const double_pack<W>& x) {
  using R = typename double_pack<W>::register_type;
  using bits = decltype(x.v < x.v);  // a vector of W 64-bit integers
  const R sign = -R{};  // -0.0 in every lane: the sign bits
  return double_pack<W>((R)((bits)x.v & ~(bits)sign));
}

}  // namespace simd

using simd::double_pack;
using simd::simd_width;
using simd::ensemble_width;

}  // namespace geomint

namespace Eigen {
/// A pack is a real scalar of W independent lanes; Eigen does not vectorise over it (it is
/// already a vector).
template <int W>
struct NumTraits<geomint::simd::double_pack<W>> : GenericNumTraits<geomint::simd::double_pack<W>> {
  using Real = geomint::double_pack<W>;
  using NonInteger = geomint::double_pack<W>;
  using Literal = geomint::double_pack<W>;
  using Nested = geomint::double_pack<W>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 0,
    ReadCost = 1,
    AddCost = 1,
    MulCost = 1
  };
  static geomint::double_pack<W> epsilon() { return std::numeric_limits<double>::epsilon(); }
  static geomint::double_pack<W> dummy_precision() { return NumTraits<double>::dummy_precision(); }
  static int digits10() { return std::numeric_limits<double>::digits10; }
};
}  // namespace Eigen
