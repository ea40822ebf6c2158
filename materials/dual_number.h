// Forward-mode dual number (value + one directional derivative) used to differentiate the
// stress functions exactly for the consistent tangent dP/dF. Usable as an Eigen scalar.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace vulnus::materials
{
/// a + b eps with eps^2 = 0: value() is the function value, derivative() the directional
/// derivative along the seeded direction. Comparisons act on the value only.
struct Dual
{
  double v = 0.0;
  double d = 0.0;

  Dual() = default;
  // Implicit on purpose: constants in templated kernels convert without ceremony.
  Dual(const double value, const double derivative = 0.0) : v(value), d(derivative) {}

  Dual& operator+=(const Dual& o)
  {
    v += o.v;
    d += o.d;
    return *this;
  }
  Dual& operator-=(const Dual& o)
  {
    v -= o.v;
    d -= o.d;
    return *this;
  }
  Dual& operator*=(const Dual& o)
  {
    d = d * o.v + v * o.d;
    v *= o.v;
    return *this;
  }
  Dual& operator/=(const Dual& o)
  {
    const double inv = 1.0 / o.v;
    d = (d - v * inv * o.d) * inv;
    v *= inv;
    return *this;
  }
};

inline Dual operator-(const Dual& a)
{
  return {-a.v, -a.d};
}
inline Dual operator+(Dual a, const Dual& b)
{
  return a += b;
}
inline Dual operator-(Dual a, const Dual& b)
{
  return a -= b;
}
inline Dual operator*(Dual a, const Dual& b)
{
  return a *= b;
}
inline Dual operator/(Dual a, const Dual& b)
{
  return a /= b;
}
inline Dual operator+(Dual a, const double b)
{
  a.v += b;
  return a;
}
inline Dual operator+(const double b, Dual a)
{
  a.v += b;
  return a;
}
inline Dual operator-(Dual a, const double b)
{
  a.v -= b;
  return a;
}
inline Dual operator-(const double b, const Dual& a)
{
  return {b - a.v, -a.d};
}
inline Dual operator*(const Dual& a, const double b)
{
  return {a.v * b, a.d * b};
}
inline Dual operator*(const double b, const Dual& a)
{
  return {a.v * b, a.d * b};
}
inline Dual operator/(const Dual& a, const double b)
{
  return {a.v / b, a.d / b};
}
inline Dual operator/(const double b, const Dual& a)
{
  return Dual(b) / a;
}

inline bool operator<(const Dual& a, const Dual& b)
{
  return a.v < b.v;
}
inline bool operator>(const Dual& a, const Dual& b)
{
  return a.v > b.v;
}
inline bool operator<=(const Dual& a, const Dual& b)
{
  return a.v <= b.v;
}
inline bool operator>=(const Dual& a, const Dual& b)
{
  return a.v >= b.v;
}
inline bool operator==(const Dual& a, const Dual& b)
{
  return a.v == b.v && a.d == b.d;
}
inline bool operator!=(const Dual& a, const Dual& b)
{
  return !(a == b);
}

inline Dual exp(const Dual& a)
{
  const double e = std::exp(a.v);
  return {e, e * a.d};
}
inline Dual log(const Dual& a)
{
  return {std::log(a.v), a.d / a.v};
}
inline Dual sqrt(const Dual& a)
{
  const double s = std::sqrt(a.v);
  return {s, 0.5 * a.d / s};
}
inline Dual pow(const Dual& a, const double p)
{
  const double ap = std::pow(a.v, p);
  return {ap, p * ap / a.v * a.d};
}
inline Dual cbrt(const Dual& a)
{
  const double c = std::cbrt(a.v);
  return {c, a.d / (3.0 * c * c)};
}
inline Dual abs(const Dual& a)
{
  return a.v < 0.0 ? -a : a;
}

inline double value_of(const double a)
{
  return a;
}
inline double value_of(const Dual& a)
{
  return a.v;
}
} // namespace vulnus::materials

namespace Eigen
{
template <> struct NumTraits<vulnus::materials::Dual> : NumTraits<double>
{
  using Real = vulnus::materials::Dual;
  using NonInteger = vulnus::materials::Dual;
  using Nested = vulnus::materials::Dual;
  using Literal = vulnus::materials::Dual;
  enum
  {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 2,
    MulCost = 3
  };
};

template <> struct ScalarBinaryOpTraits<vulnus::materials::Dual, double>
{
  using ReturnType = vulnus::materials::Dual;
};
template <> struct ScalarBinaryOpTraits<double, vulnus::materials::Dual>
{
  using ReturnType = vulnus::materials::Dual;
};
} // namespace Eigen
