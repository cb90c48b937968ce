#pragma once
// Sample points shared by the CPU reference and the SH transfer: jittered
// (stratified) grids on the unit square, hashed from a seed so that a
// result depends on its pixel or vertex alone, and Shirley & Chiu's
// concentric map (1997) onto the unit disc, which keeps strata compact and
// their areas equal.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::raytrace {

// [0, 1) from a hash's top 24 bits.
float unitFloatFromHash(uint32_t hash);

// One point per cell of an n x n grid on the unit square, row by row, each
// jittered inside its cell by hashes of `seed` and the cell's index.
std::vector<glm::vec2> jitteredGrid(int strataPerSide, uint32_t seed);

// The unit square onto the unit disc.
glm::vec2 concentricDisc(const glm::vec2& unitSquare);

}  // namespace dermis::raytrace
