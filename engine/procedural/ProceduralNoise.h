#pragma once
// Deterministic noise for the procedural maps: a seeded integer hash, 3-D
// gradient noise with its analytic gradient, and a field of pore-like dents.
// Inputs are positions in noise units (callers scale metres by a frequency).

#include <glm/glm.hpp>

#include <cstdint>

namespace dermis {

struct NoiseSample {
    float value = 0.0f;
    glm::vec3 gradient{0.0f};  // d value / d position

    NoiseSample& operator+=(const NoiseSample& other) {
        value += other.value;
        gradient += other.gradient;
        return *this;
    }
};

uint32_t hashCell(int x, int y, int z, uint32_t seed);

// Uniform in [0, 1), from the hash.
float hashUnit(uint32_t hash);

// Perlin-style gradient noise, quintic fade; values roughly in [-1, 1], zero
// at integer lattice points.
NoiseSample gradientNoise(const glm::vec3& p, uint32_t seed);

// Sum of `octaves` gradient noises, each at `lacunarity` times the frequency
// and `gain` times the amplitude of the one before.
NoiseSample fractalNoise(const glm::vec3& p, int octaves, float lacunarity, float gain, uint32_t seed);

// Value in [0, 1]: smooth and cheap, for colour variation.
float valueNoise(const glm::vec3& p, uint32_t seed);

// Dents at jittered points of a unit lattice: each kept point (a fraction
// `density` of them) adds -depth * (1 - d^2/R^2)^3 within radius R, with R and
// depth varied per point. `radius` must be at most 0.5 so that only the 2x2x2
// nearest cells can reach p. The deepest dent is about -1.
NoiseSample poreNoise(const glm::vec3& p, float radius, float density, uint32_t seed);

}  // namespace dermis
