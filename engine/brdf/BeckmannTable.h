#pragma once
// The Beckmann table of Chappuis 2011 §2.3 (listing 2.4), computed on the CPU:
// P_H(N.H, m) = exp(-tan^2(a) / m^2) / (m^2 cos^4(a)), a = acos(N.H),
// Texel (i, j) holds N.H = 1 - s^2 with s = i / (size - 1), and m = j / (size - 1).
// Indexing by s = sqrt(1 - N.H) rather than N.H puts texels evenly in angle
// near the peak (s ~ angle / sqrt 2), where a lobe with m = 0.1 is only
// 0.005 wide in N.H: a table linear in N.H would flatten it. Texel centres
// sit exactly on the sample points, so shaders look up
//   uv = (vec2(s, m) * (size - 1) + 0.5) / size.
// Where the formula is 0 * Inf (N.H -> 0, or m -> 0 away from N.H = 1) the
// limit, 0, is stored, so the table is finite everywhere.

#include <vector>

namespace dermis {

constexpr int kBeckmannTableSize = 256;

float beckmannPH(float nDotH, float m);
std::vector<float> makeBeckmannTable(int size = kBeckmannTableSize);  // row-major, row = m
float beckmannTableNDotH(int column, int size);

}  // namespace dermis
