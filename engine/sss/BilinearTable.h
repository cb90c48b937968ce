#pragma once
// Bilinear lookup in a CPU copy of a table that shaders sample with LINEAR filtering and
// CLAMP_TO_EDGE: what the sampler returns, without its 8-bit weights.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dermis {

// texels: row-major, `rows` rows of `columns`. x, y: positions in texel-centre units (texel i's
// centre at i, i.e. u * size - 1/2 for a texture coordinate u); outside the table the edge
// texels hold. The table must hold columns * rows texels.
template <class Texel>
Texel sampleBilinear(const std::vector<Texel>& texels, int columns, int rows, float x, float y) {
    const auto axis = [](float position, int size, int& i0, int& i1, float& fraction) {
        const float base = std::floor(position);
        fraction = position - base;
        i0 = std::clamp(int(base), 0, size - 1);
        i1 = std::clamp(int(base) + 1, 0, size - 1);
    };
    int x0, x1, y0, y1;
    float fx, fy;
    axis(x, columns, x0, x1, fx);
    axis(y, rows, y0, y1, fy);
    const auto texel = [&](int i, int j) { return texels[size_t(j) * size_t(columns) + size_t(i)]; };
    return glm::mix(glm::mix(texel(x0, y0), texel(x1, y0), fx), glm::mix(texel(x0, y1), texel(x1, y1), fx), fy);
}

}  // namespace dermis
