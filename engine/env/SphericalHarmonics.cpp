#include "env/SphericalHarmonics.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Solves the n x n system a x = b (Gaussian elimination, partial pivoting).
template <int N>
std::array<double, N> solve(std::array<std::array<double, N>, N> a, std::array<double, N> b) {
    for (int col = 0; col < N; ++col) {
        int pivot = col;
        for (int r = col + 1; r < N; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (int r = col + 1; r < N; ++r) {
            const double f = a[r][col] / a[col][col];
            for (int c = col; c < N; ++c) a[r][c] -= f * a[col][c];
            b[r] -= f * b[col];
        }
    }
    std::array<double, N> x{};
    for (int r = N - 1; r >= 0; --r) {
        double s = b[r];
        for (int c = r + 1; c < N; ++c) s -= a[r][c] * x[c];
        x[r] = s / a[r][r];
    }
    return x;
}

// Rotates band `Band` (its 2 Band + 1 coefficients start at Band^2) by
// matching values at fixed, independent sample directions.
template <int Band>
void rotateBand(const Sh9& in, const glm::mat3& rotation, Sh9& out) {
    constexpr int n = 2 * Band + 1;
    constexpr int first = Band * Band;
    // Directions where the band's basis functions are independent (the
    // matrix of their values is invertible): unit vectors, spread out.
    const glm::vec3 samples[5] = {glm::normalize(glm::vec3(1, 0.3f, 0.2f)), glm::normalize(glm::vec3(-0.2f, 1, 0.4f)),
                                  glm::normalize(glm::vec3(0.3f, -0.5f, 1)), glm::normalize(glm::vec3(1, 1, -0.6f)),
                                  glm::normalize(glm::vec3(-0.7f, 0.2f, -1))};
    std::array<std::array<double, n>, n> basisAtSamples{};
    for (int k = 0; k < n; ++k) {
        const auto y = shBasis(samples[k]);
        for (int j = 0; j < n; ++j) basisAtSamples[k][j] = y[first + j];
    }
    const glm::mat3 inverse = glm::transpose(rotation);
    for (int channel = 0; channel < 3; ++channel) {
        std::array<double, n> values{};
        for (int k = 0; k < n; ++k) {
            const auto y = shBasis(inverse * samples[k]);
            for (int j = 0; j < n; ++j) values[k] += double(in.coefficients[first + j][channel]) * y[first + j];
        }
        const std::array<double, n> rotated = solve<n>(basisAtSamples, values);
        for (int j = 0; j < n; ++j) out.coefficients[first + j][channel] = float(rotated[j]);
    }
}

}  // namespace

std::array<float, kShCoefficients> shBasis(const glm::vec3& d) {
    return {0.282095f,
            0.488603f * d.y,
            0.488603f * d.z,
            0.488603f * d.x,
            1.092548f * d.x * d.y,
            1.092548f * d.y * d.z,
            0.315392f * (3.0f * d.z * d.z - 1.0f),
            1.092548f * d.x * d.z,
            0.546274f * (d.x * d.x - d.y * d.y)};
}

glm::vec3 latLongDirection(int u, int v, int width, int height) {
    const double phi = 2.0 * kPi * (u + 0.5) / width;
    const double theta = kPi * (v + 0.5) / height;
    return glm::vec3(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(std::sin(theta) * std::cos(phi)));
}

float latLongTexelSolidAngle(int v, int width, int height) {
    const double theta0 = kPi * v / height, theta1 = kPi * (v + 1) / height;
    return float(2.0 * kPi / width * (std::cos(theta0) - std::cos(theta1)));
}

glm::vec2 latLongUv(const glm::vec3& direction) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
    double u = std::atan2(d.x, d.z) / (2.0 * kPi);
    if (u < 0.0) u += 1.0;
    const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    return glm::vec2(float(u), float(v));
}

Sh9 projectLatLong(const Image& map) {
    std::array<glm::dvec3, kShCoefficients> sum{};
    for (int v = 0; v < map.height; ++v) {
        const double solidAngle = latLongTexelSolidAngle(v, map.width, map.height);
        for (int u = 0; u < map.width; ++u) {
            const auto y = shBasis(latLongDirection(u, v, map.width, map.height));
            const glm::dvec3 radiance(glm::vec3(map.at(u, v)));
            for (int i = 0; i < kShCoefficients; ++i) sum[size_t(i)] += radiance * double(y[size_t(i)]) * solidAngle;
        }
    }
    Sh9 out;
    for (int i = 0; i < kShCoefficients; ++i) out.coefficients[size_t(i)] = glm::vec3(sum[size_t(i)]);
    return out;
}

glm::vec3 shIrradiance(const Sh9& light, const glm::vec3& normal) {
    const float bandWeight[3] = {float(kPi), float(2.0 * kPi / 3.0), float(kPi / 4.0)};
    const auto y = shBasis(normal);
    glm::vec3 e(0.0f);
    for (int i = 0; i < kShCoefficients; ++i) {
        const int band = i == 0 ? 0 : i < 4 ? 1 : 2;
        e += bandWeight[band] * light.coefficients[size_t(i)] * y[size_t(i)];
    }
    return e;
}

Sh9 rotateSh(const Sh9& light, const glm::mat3& rotation) {
    Sh9 out;
    out.coefficients[0] = light.coefficients[0];
    rotateBand<1>(light, rotation, out);
    rotateBand<2>(light, rotation, out);
    return out;
}

}  // namespace dermis
