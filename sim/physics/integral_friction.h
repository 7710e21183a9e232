// The integral friction model of Kudra et al. 2016 (eqs. 5 and 16): Coulomb friction integrated
// over the circular contact patch under the shifted Hertz pressure of eq. 1.
//
// Why the quadrature is built around the instantaneous centre of rotation (ICR): the local slip
// v_P = (vsx - ws y, vsy + ws x) vanishes at c = (-vsy, vsx) / ws, where its direction jumps, so
// on any grid fixed to the patch the integrand has a kink (eps_t > 0) or a discontinuity
// (eps_t = 0) and Gauss rules lose their fast convergence. In polar coordinates about c the slip
// direction depends on the angle only, and the remaining factors are smooth along each ray:
//   - c inside the patch: periodic trapezoid rule in the angle (spectral for smooth periodic
//     integrands), Gauss-Legendre along each ray with rho = R (1 - s^2), which absorbs the
//     square-root zero of the Hertz pressure at the rim;
//   - c outside the patch: the cone of rays that hits the disk, with the angle substituted as
//     alpha sin(phi) and each chord as mid + half sin(theta), which again absorbs both square
//     roots (at the rim and at the tangent rays);
//   - c far away (or ws = 0): the integrand is smooth on the disk and a polar rule about the
//     patch centre with rho = sin(theta) is used.
// The accuracy is controlled by the two orders; CalibrateQuadrature picks them for a tolerance
// and reports the error it measured.
#pragma once

#include <cmath>
#include <vector>

#include "sim/physics/contact_kinematics.h"
#include "sim/physics/gauss_legendre.h"

namespace billiard::physics {

struct QuadratureOrder {
  int angular = 64;
  int radial = 32;
};

class IntegralFriction {
 public:
  explicit IntegralFriction(QuadratureOrder order = {});

  // Tsx, Tsy, Ms of eq. 16 (eq. 5 when eps_t = 0). d_c, d_s are taken from k.
  template <typename T>
  FrictionResultant<T> Evaluate(const ContactKinematics<T>& k, double eps_t) const;

  QuadratureOrder order() const { return order_; }

 private:
  template <typename T>
  struct Sums;

  template <typename T>
  void IcrInside(const ContactKinematics<T>& k, const T& cx, const T& cy, double et2,
                 Sums<T>* sums) const;
  template <typename T>
  void IcrOutside(const ContactKinematics<T>& k, const T& cx, const T& cy, double et2,
                  Sums<T>* sums) const;
  template <typename T>
  void CentreRule(const ContactKinematics<T>& k, double et2, Sums<T>* sums) const;

  QuadratureOrder order_;
  QuadratureRule angular_rule_;                      // Gauss-Legendre, for the cone of rays
  QuadratureRule radial_rule_;                       // Gauss-Legendre, along each ray
  std::vector<double> cos_periodic_, sin_periodic_;  // trapezoid angles 2 pi j / n
};

// The measured accuracy of a quadrature order.
struct CalibratedQuadrature {
  QuadratureOrder order;
  double error_estimate = 0.0;  // max over the probe states of |F(order) - F(2 order)|
};

// The cheapest order (doubling from 16 x 8) whose estimated error over a fixed set of hard probe
// states (ICR at the centre, inside, near the rim on both sides, outside, far; pure slide; pure
// spin) is below tol, for the given eps_t and rolling-resistance parameter d. Throws
// std::runtime_error if tol cannot be reached below 4096 x 2048 nodes.
CalibratedQuadrature CalibrateQuadrature(double eps_t, double d, double tol);

// ---------------------------------------------------------------------------------------------
// Implementation.

template <typename T>
struct IntegralFriction::Sums {
  T tsx = T(0.0), tsy = T(0.0), ms = T(0.0);

  // One quadrature node at (x, y) whose weight already holds sqrt(1 - x^2 - y^2), the area
  // element and the rule's weight; the pressure's linear factor is applied here.
  void Add(const ContactKinematics<T>& k, const T& x, const T& y, const T& weight, double et2) {
    using std::sqrt;
    const T upx = k.vsx - k.ws * y;
    const T upy = k.vsy + k.ws * x;
    const T w = weight * (1.0 + k.dc * x + k.ds * y) / sqrt(upx * upx + upy * upy + et2);
    tsx += upx * w;
    tsy += upy * w;
    ms += (x * upy - y * upx) * w;
  }
};

template <typename T>
FrictionResultant<T> IntegralFriction::Evaluate(const ContactKinematics<T>& k, double eps_t) const {
  using std::abs;
  using std::sqrt;
  // Beyond this distance of the ICR (in patch radii) the integrand is smooth on the patch.
  constexpr double kFarIcr = 50.0;
  const double et2 = eps_t * eps_t;
  Sums<T> sums;
  const T vs = sqrt(k.vsx * k.vsx + k.vsy * k.vsy);
  if (abs(k.ws) * kFarIcr <= vs) {
    CentreRule(k, et2, &sums);
  } else {
    const T cx = -k.vsy / k.ws;
    const T cy = k.vsx / k.ws;
    if (cx * cx + cy * cy < 1.0) {
      IcrInside(k, cx, cy, et2, &sums);
    } else {
      IcrOutside(k, cx, cy, et2, &sums);
    }
  }
  constexpr double kPressureScale = 3.0 / (2.0 * 3.14159265358979323846);
  return {sums.tsx * kPressureScale, sums.tsy * kPressureScale, sums.ms * kPressureScale};
}

template <typename T>
void IntegralFriction::IcrInside(const ContactKinematics<T>& k, const T& cx, const T& cy,
                                 double et2, Sums<T>* sums) const {
  using std::sqrt;
  const double dpsi = 2.0 * 3.14159265358979323846 / order_.angular;
  const T q = cx * cx + cy * cy - 1.0;
  for (int j = 0; j < order_.angular; ++j) {
    const double ex = cos_periodic_[j], ey = sin_periodic_[j];
    const T b = cx * ex + cy * ey;
    const T root = sqrt(b * b - q);
    const T r_out = root - b;    // the ray leaves the patch here
    const T r_back = -root - b;  // the other root, behind the ICR
    for (std::size_t i = 0; i < radial_rule_.nodes.size(); ++i) {
      const double s = 0.5 * (1.0 + radial_rule_.nodes[i]);
      const double ws = 0.5 * radial_rule_.weights[i];
      const T rho = r_out * (1.0 - s * s);
      // sqrt(1 - |p|^2) = s sqrt(R (rho - r_back)); area rho d rho d psi with d rho = 2 R s ds.
      const T weight = s * sqrt(r_out * (rho - r_back)) * rho * 2.0 * r_out * s * (ws * dpsi);
      sums->Add(k, cx + rho * ex, cy + rho * ey, weight, et2);
    }
  }
}

template <typename T>
void IntegralFriction::IcrOutside(const ContactKinematics<T>& k, const T& cx, const T& cy,
                                  double et2, Sums<T>* sums) const {
  using std::asin;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  constexpr double kHalfPi = 1.57079632679489661923;
  const T dist = sqrt(cx * cx + cy * cy);
  const T alpha = asin(1.0 / dist);      // half-angle of the cone of rays that hit the patch
  const T psi_centre = atan2(-cy, -cx);  // the ray through the patch centre
  for (std::size_t j = 0; j < angular_rule_.nodes.size(); ++j) {
    const double phi = kHalfPi * angular_rule_.nodes[j];
    const T delta = alpha * sin(phi);
    const T dpsi = alpha * (cos(phi) * kHalfPi * angular_rule_.weights[j]);
    const T psi = psi_centre + delta;
    const T ex = cos(psi), ey = sin(psi);
    const T sin_delta = sin(delta);
    T disc = 1.0 - dist * dist * sin_delta * sin_delta;
    if (disc < 0.0) disc = T(0.0);  // rounding at the tangent ray
    const T half = sqrt(disc);
    const T mid = dist * cos(delta);
    for (std::size_t i = 0; i < radial_rule_.nodes.size(); ++i) {
      const double theta = kHalfPi * radial_rule_.nodes[i];
      const double wt = kHalfPi * radial_rule_.weights[i];
      const double ct = std::cos(theta);
      const T rho = mid + half * std::sin(theta);
      // sqrt(1 - |p|^2) = half cos(theta), d rho = half cos(theta) d theta.
      const T weight = half * half * (ct * ct * wt) * rho * dpsi;
      sums->Add(k, cx + rho * ex, cy + rho * ey, weight, et2);
    }
  }
}

template <typename T>
void IntegralFriction::CentreRule(const ContactKinematics<T>& k, double et2, Sums<T>* sums) const {
  constexpr double kQuarterPi = 0.78539816339744830962;
  const double dpsi = 2.0 * 3.14159265358979323846 / order_.angular;
  for (std::size_t i = 0; i < radial_rule_.nodes.size(); ++i) {
    const double theta = kQuarterPi * (1.0 + radial_rule_.nodes[i]);
    const double rho = std::sin(theta);
    const double ct = std::cos(theta);
    // rho = sin(theta): sqrt(1 - rho^2) d rho = cos^2(theta) d theta; area element rho.
    const double weight = ct * ct * rho * kQuarterPi * radial_rule_.weights[i] * dpsi;
    for (int j = 0; j < order_.angular; ++j) {
      sums->Add(k, T(rho * cos_periodic_[j]), T(rho * sin_periodic_[j]), T(weight), et2);
    }
  }
}

}  // namespace billiard::physics
