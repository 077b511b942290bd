// Plain d-dimensional vector value types (d = 2, 3) for positions, velocities and impulses.
// Named components (x, y, z) keep the 2D analyses readable; operator[] and the d-generic
// operators serve the engine, which is a template on d.  Sums run over the components in order
// x, y, z, so that the 2D instantiation gives exactly the bits of a hand-written 2D expression.
#pragma once

#include <cmath>

namespace granule {

template <int D>
struct Vec;

template <>
struct Vec<2> {
  double x = 0.0;
  double y = 0.0;
  static constexpr int kDimension = 2;
  constexpr double operator[](int axis) const { return axis == 0 ? x : y; }
  constexpr double& operator[](int axis) { return axis == 0 ? x : y; }
};

template <>
struct Vec<3> {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  static constexpr int kDimension = 3;
  constexpr double operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  constexpr double& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

template <int D>
constexpr Vec<D> operator+(Vec<D> a, Vec<D> b) {
  for (int k = 0; k < D; ++k) a[k] += b[k];
  return a;
}
template <int D>
constexpr Vec<D> operator-(Vec<D> a, Vec<D> b) {
  for (int k = 0; k < D; ++k) a[k] -= b[k];
  return a;
}
template <int D>
constexpr Vec<D> operator-(Vec<D> a) {
  for (int k = 0; k < D; ++k) a[k] = -a[k];
  return a;
}
template <int D>
constexpr Vec<D> operator*(double s, Vec<D> a) {
  for (int k = 0; k < D; ++k) a[k] = s * a[k];
  return a;
}
template <int D>
constexpr Vec<D> operator*(Vec<D> a, double s) {
  return s * a;
}
template <int D>
constexpr double dot(Vec<D> a, Vec<D> b) {
  double sum = a[0] * b[0];
  for (int k = 1; k < D; ++k) sum += a[k] * b[k];
  return sum;
}
template <int D>
constexpr double norm2(Vec<D> a) {
  return dot(a, a);
}
template <int D>
inline double norm(Vec<D> a) {
  return std::sqrt(norm2(a));
}
// z-component of the 2D cross product a × b.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

}  // namespace granule
