// Regime features: variables that the regression methods (GP-SR, SINDy) may use besides the
// states and inputs, computed from the states, so that a free run recomputes them from the
// simulated states (issue 19; docs/vessels/odin-hs.md, "Identifying it").
//
// A planing hull's resistance and damping change with its regime, and the regime is set by the
// Froude number Fn = U / sqrt(g L), U = sqrt(u^2 + v^2): displacement below Fn 0.4, planing
// above 1.1. Fn is the speed in the units in which the regime boundaries are of order one. That
// matters to GP-SR: its random and tuned constants are of order one, so with Fn as a variable it
// can place a hinge abs(c - Fn) at a change of regime (odin-hs: c = 0.57, the resistance hump),
// while the same hinge in u, at 6 m/s, was never found. One hinge is not enough for a curve with
// a hump, though, and the search rarely builds more; fixed hinges at quantiles of the record's
// Fn are a piecewise-linear basis that a weighted sum turns into the curve. Where the regime
// changes, and on which forces, is still left to the method: the knots follow the data, not the
// boundaries.
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"
#include "methods/method_options.h"

namespace usvid {

// A variable `name` defined by `expression` in channel names (docs/data.md#equation-syntax).
struct DerivedVariable {
  std::string name;
  std::string expression;

  // The name a method gives its column: the expression in parentheses, so that an equation
  // written with it is in channel names and a free run recomputes it from the states.
  std::string Column() const { return "(" + expression + ")"; }
};

// The regime boundaries of the Froude number (displacement | semi-displacement | planing).
inline constexpr double kDisplacementFroude = 0.4, kPlaningFroude = 1.1;

// How many hinges "hinges" places, per method: at the 1/(n+1) .. n/(n+1) quantiles of the
// record's Fn. SINDy regresses on every column at once, and eight follow odin-hs's resistance
// hump closer than four (its zig-zag 68-92 % -> 89-93 %). GP must draw each variable in its
// search: with eight, its step-grid-trained models diverged in 3 of 6 default-suite runs that
// four-hinge models passed at 92-95 % (docs/vessels/odin-hs.md).
inline constexpr int kGpFroudeHinges = 4, kSindyFroudeHinges = 8;

// GP's short-horizon simulations on a record with regime features [s]: at the knee of a
// resistance hump a surge equation a few percent off in its steady speed shows over 30 s and
// hides within the noise over 10 s; on issue 19's protocol (odin-hs, seeds 1-8) the held-out
// zig-zag reached 90 % in 8 of 8 seeds against 7 of 8 (docs/vessels/odin-hs.md).
inline constexpr double kRegimeHorizonS = 30.0;

// The features of `spec` for a vessel whose Froude number at 1 m/s is `froude_per_speed`
// (1 / sqrt(g L), VesselSimulator::FroudeNumber(1); 0: the vessel has no length):
//  "none": none;
//  "froude": Fn = sqrt(u*u + v*v) / sqrt(g L) (needs a length and channels u and v);
//  "hinges": Fn and `hinges` hinges abs(Fn - k), named Fn_k1 .., with the knots k at
//            evenly spaced quantiles of the record's Fn (rounded to 0.01, repeats dropped): a
//            basis of piecewise-linear functions of Fn. Resistance is a curve in Fn with a hump,
//            which a sum of weighted hinges follows; a search that must build each hinge and
//            tune its knot finds one or two (odin-hs: one, at the hump), so the
//            derivative's held-out r^2 stays near 0.85 where four fixed hinges give 0.98;
//  "auto": "hinges" when there is a length, the data have u and v, and the record's Fn crosses
//          a regime boundary (a record within one regime gains nothing from them), else "none".
// Throws InputError for an unknown spec, or "froude"/"hinges" without a length or without u and
// v.
std::vector<DerivedVariable> RegimeFeatures(const std::string& spec, double froude_per_speed,
                                            const Dataset& data, int hinges);

// The option "features" of a method that takes regime features, placing `hinges` hinges: one
// declaration, shared by gp and sindy.
OptionSpec RegimeFeaturesOption(int hinges);

}  // namespace usvid
