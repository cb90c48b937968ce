// Lean.glsl: LEAN mapping through the deferred SSS (Vila Verde 2015; Olano & Baker
// 2010). This header is its own manual.
//
// WHAT IT DOES
//   A LEAN map texel holds the bump centre B = n.xy / n.z and the second
//   moments M = (B.x^2, B.y^2, B.x B.y) of a tangent-space normal map
//   (engine/lean/LeanBake.h). Both are linear, so any average of texels (mip
//   levels, trilinear filtering, a blur) is exact, and the slope covariance of
//   what was averaged is Sigma = M - B B^T (Olano & Baker eq. 9). Adding the
//   base roughness (Beckmann m: slope variance m^2/2 per axis) gives a 2-D
//   Gaussian of microfacet slopes; evaluated at the half vector's slope and
//   normalised like Beckmann it is the specular lobe (Olano & Baker §3.2).
//
// ONE SPACE (Vila Verde 2015 §4.3.1 and §4.3.3)
//   The blur averages the moments of neighbouring pixels, whose tangent
//   planes differ, so the G-buffer stores them relative to one common plane:
//   the view plane (Vila Verde 2015 §4.3.1), taken per pixel perpendicular to the eye
//   ray. The frame of pixel p is the rotation of view space that takes +z onto
//   V (the unit vector to the eye) by the smallest angle:
//     X = (1 - V.x^2/(1+V.z), -V.x V.y/(1+V.z), -V.x)
//     Y = (-V.x V.y/(1+V.z), 1 - V.y^2/(1+V.z), -V.y)        Z = V
//   (Rodrigues' formula for the rotation from +z to V). For an orthographic
//   camera, and at the image centre, this is exactly the view plane. Why not
//   view z everywhere: with perspective, a visible facet has n.V > 0 but can
//   have n.z <= 0 near an off-axis silhouette, and every half vector has
//   h.V > 0 but not always h.z > 0, so slopes against z are infinite or
//   undefined exactly where rim lights put their highlights; against V they
//   are finite. Neighbouring frames differ by the pixels' angular spacing
//   (under a degree across the widest skin Gaussian at 1280x720), a slope
//   error of about 0.01, well below the lobes' widths. The composite rebuilds
//   the same frame from the pixel's position, so both ends agree (§4.3.3).
//
// THE PROJECTION (G-buffer, leanProject)
//   A tangent slope b is the facet normal n(b) = b.x T + b.y Bt + N (view
//   space, T/Bt/N the tangent frame). In the pixel frame its slope is
//     s(b) = (n.X, n.Y) / (n.V),
//   a projective map, not a linear one, so the moments are carried through
//   its first-order expansion at the mean (the delta method):
//     B' = s(B),   J = ds/db at B = [a.xy - B' a.z, c.xy - B' c.z] / (n(B).V)
//   with a = T and c = Bt in frame coordinates, and
//     Sigma' = J (Sigma_t + base) J^T,   M' = Sigma' + B' B'^T.
//   The base roughness is added before the projection, in the tangent plane
//   where it is defined, so a flat tilted surface projects to the Beckmann
//   lobe of that tilt. n(B).V is kept >= kLeanMinCos |n(B)|, so a mean
//   normal facing away (interpolated normals at silhouettes) stays finite.
//
// THE LOBE (leanSpecular)
//   With P(s) = exp(-(s-B')^T Sigma'^-1 (s-B') / 2) / (2 pi sqrt(det Sigma'))
//   the slope density, the density of facet normals per solid angle is
//   P(s_h) / (h.V)^3 (slope-to-solid-angle Jacobian), so the distribution
//   normalised over the mean plane N_m = normalize(B'.x, B'.y, 1) is
//     D(h) = P(s_h) / ((h.V)^3 (h.N_m)),   integral of D (h.N_m) dw = 1.
//   For a flat surface facing the camera this is Beckmann exactly. The BRDF
//   times the cosine is the Kelemen/Szirmay-Kalos form of include/Specular.glsl,
//   rho_s pi D F / |L + V|^2 (N_m.L), with Schlick's Fresnel (F0 = 0.028), so
//   LEAN and KS agree on a flat surface and differ only where bumps are
//   filtered. (N_m.L)/(h.N_m) <= |L + V| <= 2 because N_m.V > 0 always.
//
// THE CLAMP (leanClampCovariance)
//   Filtering in fp16 and averaging across pixels can leave Sigma slightly
//   indefinite; a bad texel can be NaN or Inf. Sigma is rebuilt from its
//   eigen-decomposition with both eigenvalues clamped to
//   [kLeanMinVariance, kLeanMaxVariance]; a non-finite or absurd entry
//   gives the widest lobe (variance kLeanMaxVariance, nearly no highlight),
//   a non-finite B gives a slope of 0. The lobe is then finite and >= 0 for
//   every input.
//
// G-BUFFER PACKING (engine/passes/GBufferPass.h)
//   lean moments  RGBA16F  (B'.x, B'.y, M'.xx, M'.yy)
//   lean cross    R16F     M'.xy
//   fp16 keeps Sigma' to about 1e-3 of M'; Sigma' grows with the tilt as
//   fast as B'B'^T does, so the relative error stays small.
//
// LIMITS
//   kLeanMinVariance  eigenvalue floor, slope^2 (1e-4: Beckmann m = 0.014,
//                     smoother than any skin; keeps 1/sqrt(det) finite)
//   kLeanMaxVariance  eigenvalue ceiling, slope^2 (1e4; fp16 holds M')
//   kLeanMinCos       floor on the mean normal's n.V / |n| (1/8: 83 degrees
//                     from the eye ray), so |B'| <= ~8. At silhouettes the
//                     interpolated normal turns away from the eye, and back
//                     faces drawn with a flipped normal point the other way:
//                     neighbours there hold opposite grazing slopes. With
//                     1/16 a blur mixing them made lone bright pixels on the
//                     silhouette (a lobe 7x the brightest elsewhere on the
//                     default head); with 1/8 none is left.
#ifndef DERMIS_LEAN_GLSL
#define DERMIS_LEAN_GLSL

#include "Specular.glsl"

const float kLeanMinVariance = 1e-4;
const float kLeanMaxVariance = 1e4;
const float kLeanMinCos = 0.125;
const float kLeanMaxSlope = sqrt(1.0 - kLeanMinCos * kLeanMinCos) / kLeanMinCos;

// The pixel's frame: rows X, Y, V, so frame * w = (w.X, w.Y, w.V).
mat3 leanFrame(vec3 V) {
    float k = 1.0 / (1.0 + max(V.z, -0.999));
    vec3 X = vec3(1.0 - V.x * V.x * k, -V.x * V.y * k, -V.x);
    vec3 Y = vec3(-V.x * V.y * k, 1.0 - V.y * V.y * k, -V.y);
    return transpose(mat3(X, Y, V));
}

// Covariance (xx, yy, xy) from first and second moments.
vec3 leanCovariance(vec2 B, vec3 M) { return vec3(M.x - B.x * B.x, M.y - B.y * B.y, M.z - B.x * B.y); }

// A symmetric 2x2 (xx, yy, xy) with both eigenvalues clamped into
// [kLeanMinVariance, kLeanMaxVariance], with its inverse and determinant taken
// from those eigenvalues. Non-finite or absurd entries give the widest
// isotropic lobe. Why not det = xx yy - xy^2 of the result: with eigenvalues
// 1e4 and 1e-4 that difference of two ~1e8 products has a rounding error of
// several units in fp32, so it came out <= 0 and sqrt(det) NaN (stress seed
// 1212: 38 NaN in the lean specular pass).
struct LeanCovariance {
    vec3 covariance;  // (xx, yy, xy)
    vec3 inverse;     // (xx, yy, xy) of the inverse
    float determinant;
};

// (xx, yy, xy) of the symmetric matrix with eigenvalues major, minor and the
// major axis at angle t, axis = (cos 2t, sin 2t).
vec3 leanSymmetric(float major, float minor, vec2 axis) {
    float centre = 0.5 * (major + minor);
    float spread = 0.5 * (major - minor);
    return vec3(centre + spread * axis.x, centre - spread * axis.x, spread * axis.y);
}

LeanCovariance leanClampCovarianceWithInverse(vec3 S) {
    // abs(NaN) <= x and abs(Inf) <= x are false: one test catches both.
    vec2 axis = vec2(1.0, 0.0);  // any axis when isotropic
    float major = kLeanMaxVariance;
    float minor = kLeanMaxVariance;
    if (all(lessThanEqual(abs(S), vec3(1e6)))) {
        float mean = 0.5 * (S.x + S.y);
        float halfDifference = 0.5 * (S.x - S.y);
        float radius = sqrt(halfDifference * halfDifference + S.z * S.z);
        if (radius > 1e-12) axis = vec2(halfDifference, S.z) / radius;
        major = clamp(mean + radius, kLeanMinVariance, kLeanMaxVariance);
        minor = clamp(mean - radius, kLeanMinVariance, kLeanMaxVariance);
    }
    LeanCovariance result;
    result.covariance = leanSymmetric(major, minor, axis);
    // The inverse: the same axes, the reciprocal eigenvalues.
    result.inverse = leanSymmetric(1.0 / major, 1.0 / minor, axis);
    result.determinant = major * minor;
    return result;
}

vec3 leanClampCovariance(vec3 S) { return leanClampCovarianceWithInverse(S).covariance; }

// A slope with NaN replaced by 0 and the magnitude kept below kLeanMaxSlope.
vec2 leanSafeSlope(vec2 B) {
    return vec2(sanitiseValue(B.x, -kLeanMaxSlope, kLeanMaxSlope, 0.0),
                sanitiseValue(B.y, -kLeanMaxSlope, kLeanMaxSlope, 0.0));
}

// Tangent-space moments (B, M = (xx, yy, xy)) plus the base slope variance,
// to the pixel frame of V. TBN columns: view-space tangent, bitangent,
// normal. Outputs are what the G-buffer stores.
void leanProject(vec2 B, vec3 M, float baseVariance, mat3 TBN, vec3 V, out vec2 viewB, out vec3 viewM) {
    B = leanSafeSlope(B);
    // Clamped once, after the projection: a congruence keeps an indefinite or
    // non-finite Sigma so, and the clamp below catches it there.
    vec3 S = leanCovariance(B, M) + vec3(baseVariance, baseVariance, 0.0);
    mat3 frame = leanFrame(V) * TBN;  // columns: T, Bt, N in frame coordinates
    vec3 n = frame * vec3(B, 1.0);
    float lengthN = length(n);
    float depth = max(n.z, kLeanMinCos * lengthN);
    viewB = n.xy / depth;
    mat2 J = mat2((frame[0].xy - viewB * frame[0].z) / depth, (frame[1].xy - viewB * frame[1].z) / depth);
    mat2 projected = J * mat2(S.x, S.z, S.z, S.y) * transpose(J);
    vec3 viewS = leanClampCovariance(vec3(projected[0][0], projected[1][1], projected[0][1]));
    viewB = leanSafeSlope(viewB);
    viewM = viewS + vec3(viewB * viewB, viewB.x * viewB.y);
}

// The mean view-space normal of tangent-space moments: the facet normal at B.
vec3 leanMeanNormal(vec2 B, mat3 TBN) { return TBN * vec3(leanSafeSlope(B), 1.0); }

// A pixel's LEAN lobe, prepared once for all its lights (leanLobe).
struct LeanLobe {
    mat3 meanFromView;        // view space to the mean plane's frame (rows T_m, B_m, N_m)
    vec3 V;                   // the view vector in that frame
    vec3 inverseCovariance;   // (xx, yy, xy) of Sigma_m^-1, slopes in the mean plane
    float peak;               // 1 / (2 pi sqrt(det Sigma_m))
};

// The lobe of pixel-frame moments (B, M) seen along unit view-space V.
LeanLobe leanLobe(vec2 B, vec3 M, vec3 V) {
    B = leanSafeSlope(B);
    LeanCovariance clamped = leanClampCovarianceWithInverse(leanCovariance(B, M));
    vec3 meanNormal = normalize(vec3(B, 1.0));  // in the pixel frame; z > 0 always
    // Back to the mean plane: its frame (rows T_m, B_m, N_m) is the smallest
    // rotation from the pixel frame's z onto N_m, and K = ds/du at u = 0 is
    // the Jacobian of the slope map from that plane to the view plane: the
    // inverse of the G-buffer's linearisation when nothing was blurred, so an
    // unblurred lobe is evaluated exactly where it was defined.
    mat3 toMean = leanFrame(meanNormal);
    mat3 axes = transpose(toMean);  // columns T_m, B_m, N_m in the pixel frame
    // Sigma_m = K^-1 S K^-T, so Sigma_m^-1 = K^T S^-1 K and det Sigma_m =
    // det S / det K^2 = det S N_m.z^6 (det K = 1 / N_m.z^3): no inverse of K.
    // S is clamped, so both are finite and positive.
    mat2 K = mat2((axes[0].xy - B * axes[0].z) / meanNormal.z, (axes[1].xy - B * axes[1].z) / meanNormal.z);
    float determinant = clamped.determinant;
    vec3 Si = clamped.inverse;
    mat2 inverseS = mat2(Si.x, Si.z, Si.z, Si.y);
    mat2 inverseMean = transpose(K) * inverseS * K;
    float cube = meanNormal.z * meanNormal.z * meanNormal.z;

    LeanLobe lobe;
    lobe.meanFromView = toMean * leanFrame(V);
    lobe.V = lobe.meanFromView * V;
    lobe.inverseCovariance = vec3(inverseMean[0][0], inverseMean[1][1], inverseMean[0][1]);
    lobe.peak = 1.0 / (2.0 * kPi * sqrt(determinant) * cube);
    return lobe;
}

// LEAN specular times N_m.L for unit view-space L and specular intensity
// rhoS: rho_s pi D F / |L + V|^2 (N_m.L), with D(h) = P(u_h) / (h.N_m)^4 and
// P the Gaussian of mean-plane slopes. >= 0 and finite for every input.
float leanSpecular(LeanLobe lobe, vec3 L, float rhoS) {
    vec3 l = lobe.meanFromView * L;
    vec3 h = l + lobe.V;
    float hLengthSquared = dot(h, h);
    if (hLengthSquared < 1e-6 || l.z <= 0.0) return 0.0;
    vec3 H = h * inversesqrt(hLengthSquared);
    if (H.z < 1e-3) return 0.0;
    vec2 u = H.xy / H.z;
    vec3 Q = lobe.inverseCovariance;
    float exponent = u.x * u.x * Q.x + 2.0 * u.x * u.y * Q.z + u.y * u.y * Q.y;
    float nDotH2 = H.z * H.z;
    float D = lobe.peak * exp(-0.5 * max(exponent, 0.0)) / (nDotH2 * nDotH2);
    // Schlick's Fresnel (Specular.glsl) with the fifth power as products.
    float base = 1.0 - clamp(dot(lobe.V, H), 0.0, 1.0);
    float base2 = base * base;
    float F = kSkinF0 + (1.0 - kSkinF0) * base2 * base2 * base;
    float value = rhoS * kPi * D * F / hLengthSquared * l.z;
    return sanitiseValue(value, 0.0, kHalfMax, 0.0);
}

// The same for one light: pixel-frame moments (B, M), unit view-space L and V.
float leanSpecular(vec2 B, vec3 M, vec3 L, vec3 V, float rhoS) { return leanSpecular(leanLobe(B, M, V), L, rhoS); }

#endif
