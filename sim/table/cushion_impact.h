// The ball meeting a cushion (a straight rail or a pocket jaw): the velocities right after the
// impact from those right before, in the cushion's frame. The event-based simulator rotates the
// ball's state into that frame, calls ResolveCushionImpact and rotates the result back.
//
// The cushion's frame: x along the cushion, y the cushion's normal pointing from the ball INTO the
// cushion, z up. The ball touches the cushion's nose at I, above its centre at the height h of the
// nose above the cloth, and the cloth at C:
//
//     sin(theta) = (h - R) / R,   n = (0, cos(theta), sin(theta))  (centre towards I),
//     r_I = R n,   r_C = (0, 0, -R).
//
// Both models treat the ball as rigid and the cushion as rigid and fixed, and leave the ball on
// the cloth (v.z() = 0 after; any vertical velocity the cushion would give is taken by the cloth).
// Both are homogeneous of degree one: scaling every input velocity scales every output.
//
// kMathavan2010 (the main model). Mathavan, Jackson and Parkin 2010, "A theoretical analysis of
// billiard ball dynamics under cushion impacts", Proc. IMechE Part C 224(9):1863-1873. Coulomb
// friction acts at both contacts during the impact: mu_w at I, mu_s at C, where the cloth's normal
// force is what keeps the ball from being pushed into the cloth by the cushion. Per unit normal
// impulse P at I, with t_I, t_C the unit slip directions at I and C,
//
//     f_I = -n - mu_w t_I,   N_C = max(0, -f_I.z),   f_C = N_C (z - mu_s t_C),
//     M dv/dP = f_I + f_C,   (2/5) M R^2 dw/dP = r_I x f_I + r_C x f_C,
//
// (the paper writes these component by component, with its slip angles phi, phi'; they are the
// same equations). They are integrated in P through compression (until the normal speed at I,
// v.y cos(theta), vanishes) and restitution, which ends when the normal force at I has given back
// e_e^2 of the work W it absorbed in compression (the energetic coefficient of restitution). With
// no friction the normal speed ratio is exactly e_e; with friction it is exactly e_e whenever the
// slip at I and at C keeps its direction through the impact (then v.y is linear in P), and
// otherwise lower: 0.84 head-on without spin with Mathavan's snooker set (e_e = 0.98), the spin
// the friction gives taking the rest. e_e = 0 leaves the ball at the cushion (v.y' = 0). Where a
// slip reaches zero the contact grips (rolls): the explicit steps then chatter about zero slip,
// which is Coulomb's static friction to the order of one step. Should the cushion's friction pull
// the ball up (f_I.z > 0, possible only if mu_w > tan(theta)) the cloth exerts no force
// (N_C = 0). About 500 steps of impulse whatever the speed: the costly model. Mathavan 2010 report
// the rigid cushion valid for normal speeds up to about 2.5 m/s; above that its deformation
// matters.
//
// kHan2005 (the cheap closed form). Han 2005, "Dynamics in carom and three cushion billiards",
// J. Mech. Sci. Technol. 19(4):976-984, eqs. 14-23: a single impulse at I on a free sphere, with
// Newton's restitution on the normal speed at I and Coulomb friction mu_w; the cloth plays no part
// (cloth_friction is not read). With u_n = v.y cos(theta) and s the slip at I,
//
//     P_n = (1 + e_e) M u_n,   P_t = min(2/7 M |s|, mu_w P_n)   (grip, or slide throughout),
//     J = -P_n n - P_t s / |s|,   v' = v + J / M,   w' = w + r_I x J / ((2/5) M R^2),
//
// and the vertical part of v' is dropped. Because the free sphere's normal mass at I is M, not
// the M / cos^2(theta) of a ball held on the cloth, the normal speed ratio without friction is
// (1 + e_e) cos^2(theta) - 1, which is e_e only when the nose is at the ball's centre height.
// The caller must expect v.y' > 0 from this model (the ball still going into the cushion) where
// (1 + e_e) cos(theta) (cos(theta) - mu_w sin(theta)) < 1 (the friction impulse's part along y
// is at most mu_w sin(theta) P_n): without friction where e_e < 0.19 with the nose at 0.7 D; never
// with the recommended sets. Mathavan's model always returns v.y' <= 0.
//
// Recommended parameters (kPoolCushion, kSnookerCushion, kCaromCushion below) and their sources:
//   snooker, 52.5 mm balls: h = 7R/5 = 36.75 mm, e_e = 0.98, mu_w = 0.14, mu_s = 0.212, all as
//     used by Mathavan 2010 (e_e and mu_w found there from the authors' measured rebounds; mu_s
//     the cloth's sliding friction from their measurements, Mathavan et al. 2009, Am. J. Phys.).
//   pool, 57.15 mm balls: h = 0.635 D = 36.29 mm (WPA equipment specifications: the nose at
//     about 63.5 % of the ball's diameter; pooltool takes 64 %); e_e = 0.85, mu_w = 0.2,
//     mu_s = 0.2, pooltool's defaults for pool (github.com/ekiefl/pooltool, BallParams
//     POOL_GENERIC, whose comment calls them not well researched).
//   carom, 61.5 mm balls: h = 37 mm (UMB rules, as pooltool's BilliardTableSpecs cites them);
//     e_e = 0.85, mu_w = 0.15, mu_s = 0.2, pooltool's BILLIARD_GENERIC defaults.
// No measurement fits e_e and mu_w for pool or carom cushions with these models; treat those as
// starting values for identification from the robot's own rebounds.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sim/physics/parameters.h"

namespace billiard::table {

struct CushionParameters {
  double height = 0.0;          // h: the cushion nose above the cloth [m], R <= h < 2R
  double restitution = 0.0;     // e_e, ball-cushion, 0..1
  double friction = 0.0;        // mu_w, ball-cushion sliding friction, >= 0
  double cloth_friction = 0.0;  // mu_s, ball-cloth, acting during the impact, >= 0
};

inline constexpr CushionParameters kSnookerCushion{0.7 * 0.0525, 0.98, 0.14, 0.212};
inline constexpr CushionParameters kPoolCushion{0.635 * 0.05715, 0.85, 0.2, 0.2};
inline constexpr CushionParameters kCaromCushion{0.037, 0.85, 0.15, 0.2};

enum class CushionModel { kMathavan2010, kHan2005 };

// "mathavan-2010" or "han-2005"; ParseCushionModel reads them back (std::nullopt otherwise).
const char* CushionModelName(CushionModel model);
std::optional<CushionModel> ParseCushionModel(const std::string& name);

// The ball's velocity and angular velocity in the cushion's frame. The ball approaches:
// v.y() > 0. v.z() is 0 on entry (it is not read).
struct ImpactVelocities {
  Eigen::Vector3d v;
  Eigen::Vector3d w;
};

// The velocities after the impact (v.z() = 0: the ball stays on the cloth). Throws
// std::invalid_argument, with a one-line reason, if v.y() <= 0, a value is not finite, a parameter
// is outside the range given above, or (kMathavan2010) the friction is so high that the impulse at
// the cushion could push the ball further in rather than stop it:
// cos(theta) <= mu_w sin(theta) + mu_s (sin(theta) + mu_w cos(theta)).
// kMathavan2010 takes `mathavan_steps` explicit steps per M v.y of normal impulse (compression
// takes about this many); the default's accuracy is given in cushion_impact.cc. A search whose
// answer the default then checks may take fewer: the error is first order in the step. Throws
// std::invalid_argument where it is below 1 or not finite.
constexpr double kMathavanSteps = 250.0;
ImpactVelocities ResolveCushionImpact(CushionModel model, const ImpactVelocities& before,
                                      const physics::BallParameters& ball,
                                      const CushionParameters& cushion,
                                      double mathavan_steps = kMathavanSteps);

}  // namespace billiard::table
