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

// Band 2's basis at five fixed directions where its functions are
// independent (the matrix of their values is invertible), and that matrix's
// inverse: a rotated band's coefficients are the inverse applied to the
// unrotated function's values at the directions.
constexpr int kBand2First = 4;
constexpr int kBand2Size = 5;
using Matrix5 = std::array<std::array<double, kBand2Size>, kBand2Size>;

const std::array<glm::vec3, kBand2Size>& band2Samples() {
    static const std::array<glm::vec3, kBand2Size> samples = {
        glm::normalize(glm::vec3(1, 0.3f, 0.2f)), glm::normalize(glm::vec3(-0.2f, 1, 0.4f)),
        glm::normalize(glm::vec3(0.3f, -0.5f, 1)), glm::normalize(glm::vec3(1, 1, -0.6f)),
        glm::normalize(glm::vec3(-0.7f, 0.2f, -1))};
    return samples;
}

const Matrix5& band2SampleInverse() {
    static const Matrix5 inverse = [] {
        Matrix5 basisAtSamples{};
        for (int s = 0; s < kBand2Size; ++s) {
            const auto y = shBasis(band2Samples()[size_t(s)]);
            for (int k = 0; k < kBand2Size; ++k) basisAtSamples[size_t(s)][size_t(k)] = y[size_t(kBand2First + k)];
        }
        Matrix5 out{};
        for (int column = 0; column < kBand2Size; ++column) {
            std::array<double, kBand2Size> unit{};
            unit[size_t(column)] = 1.0;
            const auto solved = solve<kBand2Size>(basisAtSamples, unit);
            for (int row = 0; row < kBand2Size; ++row) out[size_t(row)][size_t(column)] = solved[size_t(row)];
        }
        return out;
    }();
    return inverse;
}

}  // namespace

ShScalar9 shBasis(const glm::vec3& d) {
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

ShRotation makeShRotation(const glm::mat3& rotation) {
    ShRotation out;
    // Band 1 is c1 (t . d) with t = (c11, c1-1, c10): rotated, t becomes
    // rotation x t; in basis order (y, z, x) that is the rotation's rows and
    // columns permuted.
    constexpr int kAxisOfBand1[3] = {1, 2, 0};
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            out.band1[size_t(row)][size_t(column)] = rotation[kAxisOfBand1[column]][kAxisOfBand1[row]];
    // Band 2: values of the rotated basis at the samples, then the inverse.
    const glm::mat3 inverse = glm::transpose(rotation);
    Matrix5 rotatedAtSamples{};
    for (int s = 0; s < kBand2Size; ++s) {
        const auto y = shBasis(inverse * band2Samples()[size_t(s)]);
        for (int k = 0; k < kBand2Size; ++k) rotatedAtSamples[size_t(s)][size_t(k)] = y[size_t(kBand2First + k)];
    }
    const Matrix5& sampleInverse = band2SampleInverse();
    for (int row = 0; row < kBand2Size; ++row)
        for (int column = 0; column < kBand2Size; ++column) {
            double sum = 0.0;
            for (int s = 0; s < kBand2Size; ++s) sum += sampleInverse[size_t(row)][size_t(s)] * rotatedAtSamples[size_t(s)][size_t(column)];
            out.band2[size_t(row)][size_t(column)] = float(sum);
        }
    return out;
}

ShScalar9 applyShRotation(const ShRotation& rotation, const ShScalar9& in) {
    ShScalar9 out{};
    out[0] = in[0];
    for (size_t row = 0; row < 3; ++row)
        for (size_t column = 0; column < 3; ++column) out[1 + row] += rotation.band1[row][column] * in[1 + column];
    for (size_t row = 0; row < 5; ++row)
        for (size_t column = 0; column < 5; ++column) out[4 + row] += rotation.band2[row][column] * in[4 + column];
    return out;
}

Sh9 rotateSh(const Sh9& light, const glm::mat3& rotation) {
    const ShRotation bands = makeShRotation(rotation);
    Sh9 out;
    for (int channel = 0; channel < 3; ++channel) {
        ShScalar9 in{};
        for (size_t i = 0; i < size_t(kShCoefficients); ++i) in[i] = light.coefficients[i][channel];
        const ShScalar9 rotated = applyShRotation(bands, in);
        for (size_t i = 0; i < size_t(kShCoefficients); ++i) out.coefficients[i][channel] = rotated[i];
    }
    return out;
}

}  // namespace dermis
