#include "procedural/ProceduralNoise.h"

#include "core/Hash.h"

#include <cmath>

namespace dermis {
namespace {

// Perlin's twelve cube-edge directions, padded to sixteen.
const glm::vec3 kGradients[16] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 1}, {0, -1, -1},
};

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
float fadeDerivative(float t) { return 30.0f * t * t * (t - 1.0f) * (t - 1.0f); }
float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

glm::ivec3 floorCell(const glm::vec3& p) {
    return glm::ivec3(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)),
                      static_cast<int>(std::floor(p.z)));
}

}  // namespace

uint32_t hashCell(int x, int y, int z, uint32_t seed) {
    // Odd multipliers spread the lattice coordinates before one mixing round.
    const uint32_t h = static_cast<uint32_t>(x) * 0x8da6b343u + static_cast<uint32_t>(y) * 0xd8163841u +
                       static_cast<uint32_t>(z) * 0xcb1ab31fu + seed * 0x9e3779b9u;
    return lowbias32(h);
}

float hashUnit(uint32_t hash) { return static_cast<float>(hash >> 8) * (1.0f / 16777216.0f); }

NoiseSample gradientNoise(const glm::vec3& p, uint32_t seed) {
    const glm::ivec3 cell = floorCell(p);
    const glm::vec3 f = p - glm::vec3(cell);
    const glm::vec3 w(fade(f.x), fade(f.y), fade(f.z));
    const glm::vec3 dw(fadeDerivative(f.x), fadeDerivative(f.y), fadeDerivative(f.z));

    NoiseSample result;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 c((corner & 1), (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::vec3 g = kGradients[hashCell(cell.x + c.x, cell.y + c.y, cell.z + c.z, seed) & 15u];
        const glm::vec3 offset = f - glm::vec3(c);
        const float v = glm::dot(g, offset);
        // Trilinear weight of this corner and its derivative along each axis.
        const glm::vec3 axisWeight(c.x ? w.x : 1.0f - w.x, c.y ? w.y : 1.0f - w.y, c.z ? w.z : 1.0f - w.z);
        const glm::vec3 axisSlope(c.x ? dw.x : -dw.x, c.y ? dw.y : -dw.y, c.z ? dw.z : -dw.z);
        const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
        result.value += weight * v;
        result.gradient += weight * g;
        result.gradient += v * glm::vec3(axisSlope.x * axisWeight.y * axisWeight.z,
                                         axisWeight.x * axisSlope.y * axisWeight.z,
                                         axisWeight.x * axisWeight.y * axisSlope.z);
    }
    return result;
}

NoiseSample fractalNoise(const glm::vec3& p, int octaves, float lacunarity, float gain, uint32_t seed) {
    NoiseSample sum;
    float frequency = 1.0f;
    float amplitude = 1.0f;
    for (int octave = 0; octave < octaves; ++octave) {
        NoiseSample n = gradientNoise(p * frequency, seed + static_cast<uint32_t>(octave) * 101u);
        sum.value += amplitude * n.value;
        sum.gradient += amplitude * frequency * n.gradient;
        frequency *= lacunarity;
        amplitude *= gain;
    }
    return sum;
}

float valueNoise(const glm::vec3& p, uint32_t seed) {
    const glm::ivec3 cell = floorCell(p);
    const glm::vec3 f = p - glm::vec3(cell);
    const glm::vec3 w(smooth(f.x), smooth(f.y), smooth(f.z));
    float result = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 c((corner & 1), (corner >> 1) & 1, (corner >> 2) & 1);
        const float v = hashUnit(hashCell(cell.x + c.x, cell.y + c.y, cell.z + c.z, seed));
        result += v * (c.x ? w.x : 1.0f - w.x) * (c.y ? w.y : 1.0f - w.y) * (c.z ? w.z : 1.0f - w.z);
    }
    return result;
}

NoiseSample poreNoise(const glm::vec3& p, float radius, float density, uint32_t seed) {
    const glm::ivec3 cell = floorCell(p);
    const glm::vec3 f = p - glm::vec3(cell);
    // The nearer neighbour along each axis; farther cells are beyond reach.
    const glm::ivec3 first(f.x < 0.5f ? -1 : 0, f.y < 0.5f ? -1 : 0, f.z < 0.5f ? -1 : 0);

    NoiseSample result;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 c = cell + first + glm::ivec3((corner & 1), (corner >> 1) & 1, (corner >> 2) & 1);
        // One hash gives the keep test and the jitter (a byte each), a second
        // the radius and depth.
        const uint32_t h = hashCell(c.x, c.y, c.z, seed);
        if (static_cast<float>(h & 0xffu) * (1.0f / 256.0f) >= density) continue;
        constexpr float kByte = 1.0f / 256.0f;
        const float jx = (static_cast<float>((h >> 8) & 0xffu) + 0.5f) * kByte;
        const float jy = (static_cast<float>((h >> 16) & 0xffu) + 0.5f) * kByte;
        const float jz = (static_cast<float>(h >> 24) + 0.5f) * kByte;
        const uint32_t h2 = lowbias32(h);
        const float r = radius * (0.6f + 0.4f * static_cast<float>(h2 & 0xffffu) * (1.0f / 65536.0f));
        const float depth = 0.5f + 0.5f * static_cast<float>(h2 >> 16) * (1.0f / 65536.0f);

        const glm::vec3 d = p - (glm::vec3(c) + glm::vec3(jx, jy, jz));
        const float distanceSq = glm::dot(d, d);
        const float rSq = r * r;
        if (distanceSq >= rSq) continue;
        const float x = 1.0f - distanceSq / rSq;
        result.value -= depth * x * x * x;
        result.gradient += (6.0f * depth * x * x / rSq) * d;
    }
    return result;
}

}  // namespace dermis
