#pragma once
// A tileable bump field as a tangent-space normal map, for tests of filtered
// normals (LEAN, the texture-space irradiance's mip level).

#include "core/Image.h"

namespace dermis::test {

// A tileable bump field: the gradient of a sum of sinusoids with integer
// frequencies (so the map wraps) in random directions and phases. With many
// terms the slopes are close to Gaussian, which is what LEAN assumes; each
// axis has standard deviation `slopeStdDev`.
Image bumpNormalMap(int size, int terms, float minPeriodTexels, float maxPeriodTexels, float slopeStdDev,
                    unsigned seed);

}  // namespace dermis::test
