#pragma once
// Nine-coefficient (bands 0-2) spherical harmonics of environment light,
// after Ramamoorthi & Hanrahan 2001: projection of a latitude-longitude map
// with each texel weighted by its exact solid angle, the irradiance of the
// projected light, and rotation of the coefficients (Chappuis 2011 §3.4).
//
// Basis (real, orthonormal; direction d = (x, y, z), unit):
//   Y00 = 0.282095
//   Y1-1 = 0.488603 y,  Y10 = 0.488603 z,  Y11 = 0.488603 x
//   Y2-2 = 1.092548 xy, Y2-1 = 1.092548 yz, Y20 = 0.315392 (3z^2 - 1),
//   Y21 = 1.092548 xz,  Y22 = 0.546274 (x^2 - y^2)
// in that order (index l^2 + l + m).
//
// Irradiance (Ramamoorthi & Hanrahan 2001, eq. 7-8): E(n) = sum_lm A_l L_lm
// Y_lm(n), with A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4: the clamped cosine's
// band-limited convolution.
//
// Rotation: band l's coefficients transform by a (2l+1)^2 matrix. Chappuis
// 2011 §3.4 builds it from Z and X(+-90 degree) factors of a ZYZ rotation;
// here band 1's matrix is the rotation itself (its basis is the direction's
// y, z, x) and band 2's is solved from 5 sample directions instead (the band
// is closed under rotation, so its coefficients are fixed exactly by the
// values at any 5 directions where the basis is independent): the same
// matrices, for any rotation, without Euler angles.
//
// Lat-long layout: column u covers longitude phi = 2 pi (u + 0.5) / W about
// +Y (the up axis), row v colatitude theta = pi (v + 0.5) / H from +Y (row 0
// at the top); d = (sin theta sin phi, cos theta, sin theta cos phi).

#include "core/Image.h"

#include <glm/glm.hpp>

#include <array>

namespace dermis {

constexpr int kShCoefficients = 9;

struct Sh9 {
    std::array<glm::vec3, kShCoefficients> coefficients{};  // RGB per basis function
};

// One channel's nine coefficients (a transfer vector, one colour of a light).
using ShScalar9 = std::array<float, kShCoefficients>;

ShScalar9 shBasis(const glm::vec3& direction);

// The unit direction of a lat-long texel's centre, and its exact solid angle.
glm::vec3 latLongDirection(int u, int v, int width, int height);
float latLongTexelSolidAngle(int v, int width, int height);
// The inverse of latLongDirection as texture coordinates: u = phi / (2 pi) in
// [0, 1), v = theta / pi in [0, 1]; a texel's centre direction gives
// ((u + 0.5) / width, (v + 0.5) / height). The poles read u = 0.
glm::vec2 latLongUv(const glm::vec3& direction);

// Projects the map's RGB radiance: L_lm = sum over texels of L Y_lm d_omega.
Sh9 projectLatLong(const Image& map);

// Irradiance at normal n of the band-limited light.
glm::vec3 shIrradiance(const Sh9& light, const glm::vec3& normal);

// The coefficients of the light rotated by `rotation` (a rotation matrix):
// rotated(d) = light(rotation^T d).
Sh9 rotateSh(const Sh9& light, const glm::mat3& rotation);

// The band matrices of one rotation (row-major, acting on the band's
// coefficients in basis order; band 0 is unchanged): built once, applied to
// any number of coefficient sets. rotateSh and rotateTransfer
// (env/ShTransfer.h) both use it.
struct ShRotation {
    std::array<std::array<float, 3>, 3> band1{};
    std::array<std::array<float, 5>, 5> band2{};
};

ShRotation makeShRotation(const glm::mat3& rotation);

// The coefficients of f rotated: rotated(d) = f(rotation^T d).
ShScalar9 applyShRotation(const ShRotation& rotation, const ShScalar9& coefficients);

}  // namespace dermis
