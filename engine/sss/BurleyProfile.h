#pragma once
// Burley's normalized diffusion (Christensen & Burley 2015) as a radial profile, and its
// least-squares fit by a sum of Gaussians so that it can serve as a DiffusionProfile
// (docs/screen-space.md, "Burley's normalized diffusion").
//
// Christensen & Burley 2015 give R(r) = A s (e^(-s r) + e^(-s r / 3)) / (8 pi r), which
// integrates to A over the plane. Dermis keeps the colour in the albedo texture, so the
// profile here is R / A with s = 1/d:
//   R(r) = (e^(-r/d) + e^(-r/(3d))) / (8 pi d r)    [1/mm^2]
// and its CDF over the plane (the fraction of the exitant light within radius r),
// integrating 2 pi r R(r) = (e^(-r/d) + e^(-r/(3d))) / (4d) from 0 to r:
//   F(r) = 1 - e^(-r/d) / 4 - 3 e^(-r/(3d)) / 4.
//
// The shape distance d comes from the mean free path l and the surface albedo A by
// Christensen & Burley 2015's fit for the searchlight configuration against the mean free
// path: d = l / s(A), s(A) = 1.85 - A + 7 |A - 0.8|^3.

#include "core/Result.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <string>

namespace dermis {

// s(A) = 1.85 - A + 7 |A - 0.8|^3 (Christensen & Burley 2015, searchlight, mean free path).
double burleyScalingFactor(double albedo);
// d = l / s(A) per channel, in mm.
glm::dvec3 burleyShapeDistanceMm(const BurleyParameters& parameters);

// The normalised profile R(r) for shape distance d (both in mm; 1/mm^2, infinite at r = 0)
// and its CDF over the plane F(r), as in the header comment.
double burleyRadialProfile(double radiusMm, double shapeDistanceMm);
double burleyRadialCdf(double radiusMm, double shapeDistanceMm);
// The same per channel, d from burleyShapeDistanceMm.
glm::dvec3 burleyRadialProfile(const BurleyParameters& parameters, double radiusMm);
glm::dvec3 burleyRadialCdf(const BurleyParameters& parameters, double radiusMm);

// Albedo finite and in [0, 1], mean free path finite and > 0, per channel.
Status validateBurleyParameters(const BurleyParameters& parameters);

// A DiffusionProfile's radial CDF, sum_i w_i (1 - exp(-r^2 / 2 v_i)).
glm::dvec3 gaussianRadialCdf(const DiffusionProfile& profile, double radiusMm);

// A sum of `gaussians` Gaussians (1 to kMaxBurleyGaussians) fitted to the normalised
// profile: variances on a geometric series v_i = v_0 q^i shared by the channels (v_0 and q
// by a grid search that minimises the worst channel's largest CDF error), weights per channel
// by non-negative least squares on samples of 2 pi r R(r), normalised by DiffusionProfile::create.
// The profile keeps `parameters` (DiffusionProfile::burley()).
constexpr int kMaxBurleyGaussians = 8;
Result<DiffusionProfile> fitBurleyGaussians(const BurleyParameters& parameters, int gaussians = 6,
                                            std::string name = "burley");

struct BurleyFitError {
    // || 2 pi r (R_fit - R) || / || 2 pi r R || over 1e-5 d <= r <= 24 d, per channel.
    glm::dvec3 relativeL2{0.0};
    // max over r of |F_fit(r) - F(r)|, per channel. The edge response (docs/reference.md)
    // is off by at most half of this (see BurleyProfile.cpp).
    glm::dvec3 largestCdfError{0.0};
};
BurleyFitError measureBurleyFit(const BurleyParameters& parameters, const DiffusionProfile& profile);

}  // namespace dermis
