#pragma once
// A dominant light taken out of an environment map (docs/environment.md,
// "The dominant light"): the brightest compact region (a sun, a soft box) is
// cut out of the lat-long map and given to the frame as a sized directional
// light, which casts a PCSS shadow and lights the SSS like any scene light;
// what is left (the remainder) feeds the SH irradiance and the prefiltered
// specular.
//
// The region: the texels connected to the brightest texel (4-neighbours; u
// wraps at the seam, a row crosses a pole to the texel half a turn away)
// whose luminance is at least thresholdOverMean x the map's mean luminance
// (meanLuminance, over solid angle: the radiance of a uniform map of the same
// power; a sun raises it, a dark ground does not lower it to where clouds and
// a hazy horizon pass, as it would the median). It is extracted only
// when its solid angle is at most maxSolidAngleSr: a larger bright area is
// not a light but part of the sky; it stays, and the brightest texel outside
// it starts the next try. In the remainder the region holds `fill`,
// the mean radiance of the texels bordering it (per channel at most the
// region's own mean), so that the sky behind a sun stays sky.
//
// The light (its radiance L minus the fill, integrated over the region):
//   direction  c = normalise(sum lum(L - fill) omega d_omega), map space;
//   irradiance E_c = sum (L - fill) (omega . c) d_omega per channel: the
//              region's irradiance on a plane facing c, exactly what a
//              directional light of that irradiance gives there;
//   size       the angular diameter 2 acos(1 - Omega / 2 pi) of a cone of
//              the region's solid angle Omega.
// Energy: a plane facing c receives E_c from the light plus the remainder's
// irradiance, the same as from the original map (to float rounding); for
// normals within 90 degrees minus the light's radius of c, so does every
// other plane. Only near the terminator does a point light differ from the
// region (it ends sharply where the region fades over its own angular size).

#include "core/Image.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

struct LightExtractionSettings {
    float thresholdOverMean = 8.0f;  // a region's texels are this many times the mean luminance or brighter
    float maxSolidAngleSr = 0.0f;      // a larger region is not extracted
    int maxLights = 1;                 // regions taken out one after the other, brightest first
};

struct ExtractedLight {
    glm::vec3 towardsLight{0.0f, 1.0f, 0.0f};  // map space, unit
    glm::vec3 irradiance{0.0f};                // RGB, on a plane facing towardsLight
    float solidAngleSr = 0.0f;
    float angularDiameterDeg = 0.0f;
    glm::vec3 fill{0.0f};  // the radiance left in the region
    int texels = 0;
};

struct EnvironmentSplit {
    Image remainder;                     // the map with each region replaced by its fill
    std::vector<ExtractedLight> lights;  // brightest first; empty: remainder is the map
    std::string why;                     // why no (further) light was taken, for the log
};

// The luminance averaged over the sphere, and the one below which half the
// sphere's solid angle lies (both weighted by solid angle).
float meanLuminance(const Image& map);
float medianLuminance(const Image& map);

// `map`: a checked lat-long map (env/EnvironmentMap.h).
EnvironmentSplit extractDominantLights(const Image& map, const LightExtractionSettings& settings);

// The full angle of the cone of solid angle `solidAngleSr` (at most 4 pi).
float coneAngularDiameterDeg(float solidAngleSr);

}  // namespace dermis
