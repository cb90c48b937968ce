#include "reference/ReferenceLighting.h"

#include "gpu/UniformBlocks.h"
#include "brdf/EnergyTable.h"
#include "core/Hash.h"
#include "import/EnvironmentSource.h"
#include "raytrace/Sampling.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace dermis::reference {
namespace {

// Shadow rays start this far off the surface, on the light's side of the
// triangle's plane: far below the narrowest profile width (80 um).
constexpr float kShadowOffsetM = 1e-5f;

float smoothstep(float edge0, float edge1, float x) {
    if (!(edge1 != edge0)) return x < edge0 ? 0.0f : 1.0f;
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Van der Corput's radical inverse in base 2: the second coordinate of the
// Hammersley set.
float radicalInverse2(uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return float(double(i) / 4294967296.0);
}

// The Hammersley set of `count` points on the unit square, each centred in its stratum.
std::vector<glm::vec2> hammersleySquare(int count) {
    std::vector<glm::vec2> points;
    for (int i = 0; i < count; ++i) {
        points.emplace_back((float(i) + 0.5f) / float(count), radicalInverse2(uint32_t(i)) + 0.5f / float(count));
    }
    return points;
}

// A stratified (Hammersley) set on the unit square, taken onto the unit disc by
// the concentric map, which keeps the strata's areas.
std::vector<glm::vec2> discSamples(int count) {
    std::vector<glm::vec2> samples;
    for (const glm::vec2& p : hammersleySquare(count)) samples.push_back(raytrace::concentricDisc(p));
    return samples;
}

// Two unit vectors that make a right-handed orthonormal frame with the unit `axis`.
void tangentFrame(const glm::vec3& axis, glm::vec3& t, glm::vec3& b) {
    t = glm::normalize(glm::cross(axis, std::fabs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    b = glm::cross(axis, t);
}

// Where rays towards `direction` leave the point: from the smooth surface
// (Hanika 2021) when the interpolated normal faces the direction, else from
// the facet itself; just off the facet's plane on the ray's side.
glm::vec3 rayOrigin(const SurfacePoint& point, const glm::vec3& direction) {
    const float side = glm::dot(point.geometricNormal, direction) >= 0.0f ? 1.0f : -1.0f;
    const glm::vec3 lift = glm::dot(point.smoothNormal, direction) >= 0.0f ? point.rayLiftM : glm::vec3(0.0f);
    return point.positionM + lift + point.geometricNormal * (side * kShadowOffsetM);
}

// A hash of the point's position bits: the seed of its environment samples, so
// that they depend on the point alone (not on the thread or the call order).
uint32_t positionSeed(const glm::vec3& positionM) {
    uint32_t seed = 0x9e3779b9u;
    for (int i = 0; i < 3; ++i) {
        uint32_t bits = 0;
        std::memcpy(&bits, &positionM[i], sizeof bits);
        seed = lowbias32(seed ^ bits);
    }
    return seed;
}

// A uniform number in [0, 1) from a hash: its top 24 bits.
float unitFromHash(uint32_t hash) { return float(hash >> 8) * (1.0f / 16777216.0f); }

// `p` shifted by `shift` modulo 1 (Cranley & Patterson 1976): a stratified set
// stays stratified and each point becomes uniform.
glm::vec2 shiftedModuloOne(const glm::vec2& p, const glm::vec2& shift) {
    constexpr float kBelowOne = 0x1.fffffep-1f;
    glm::vec2 q = p + shift;
    for (int i = 0; i < 2; ++i) q[i] = std::min(q[i] >= 1.0f ? q[i] - 1.0f : q[i], kBelowOne);
    return q;
}

// A unit direction within the cone of half-angle asin(sinRadius) around `axis`,
// for the disc point `p`: uniform in solid angle when `p` is uniform over the
// disc, as cos(theta) = 1 - |p|^2 (1 - cos(radius)).
glm::vec3 coneDirection(const glm::vec3& axis, float sinRadius, const glm::vec2& p) {
    glm::vec3 t, b;
    tangentFrame(axis, t, b);
    const double sinR = sinRadius;
    const double oneMinusCosR = sinR * sinR / (1.0 + std::sqrt(std::max(0.0, 1.0 - sinR * sinR)));
    const double r2 = double(glm::dot(p, p));
    if (r2 <= 0.0) return axis;
    const double oneMinusCos = r2 * oneMinusCosR;
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    const glm::vec2 unit = p / float(std::sqrt(r2));
    return glm::normalize(float(1.0 - oneMinusCos) * axis + float(sinTheta) * (unit.x * t + unit.y * b));
}

}  // namespace

Result<ReferenceLighting> ReferenceLighting::create(const Scene& scene, const raytrace::TriangleScene& occluders,
                                                    int environmentSamples) {
    if (environmentSamples < kMinEnvironmentSamples || environmentSamples > kMaxEnvironmentSamples) {
        return makeError("reference", "the environment samples must be from " + std::to_string(kMinEnvironmentSamples) +
                                          " to " + std::to_string(kMaxEnvironmentSamples) + " (got " +
                                          std::to_string(environmentSamples) + ")");
    }
    Image environmentMap;
    if (scene.environment.enabled()) {
        auto loaded = loadEnvironmentSource(scene.environment);
        if (!loaded.ok()) return atSceneKey(scene, "/environment/source", loaded.error());
        environmentMap = std::move(*loaded);
    }
    return ReferenceLighting(scene, occluders, std::move(environmentMap), environmentSamples);
}

ReferenceLighting::ReferenceLighting(const Scene& scene, const raytrace::TriangleScene& occluders, Image environmentMap,
                                     int environmentSamples)
    : mOccluders(&occluders),
      mDiscSamples(discSamples(kAreaLightSamples)),
      mAmbient(scene.settings.ambient),
      mEnergyConservation(scene.settings.energyConservation),
      mEnergyTable(makeEnergyTable(kEnergyTableSize)),
      mEnvironment(std::move(environmentMap)),
      mEnvironmentIntensity(scene.environment.intensity),
      // The reference renders scene time 0, as it poses animated characters.
      mWorldFromMap(scene.environment.worldFromMap(0.0f)) {
    const int samples = std::clamp(environmentSamples, kMinEnvironmentSamples, kMaxEnvironmentSamples);
    const int mapSamples = mEnvironment.canSample() ? samples / 2 : 0;
    mMapSquareSamples = hammersleySquare(mapSamples);
    mCosineSquareSamples = hammersleySquare(samples - mapSamples);
    const size_t count = std::min<size_t>(scene.lights.size(), DERMIS_MAX_LIGHTS);
    int shadowedCount = 0;
    for (size_t i = 0; i < count; ++i) {
        const Light& light = scene.lights[i];
        PreparedLight prepared;
        prepared.type = light.type == LightType::Directional ? DERMIS_LIGHT_DIRECTIONAL
                        : light.type == LightType::Spot      ? DERMIS_LIGHT_SPOT
                                                             : DERMIS_LIGHT_POINT;
        prepared.positionM = light.positionM;
        prepared.direction = glm::normalize(light.direction);
        prepared.radiance = light.colour * light.intensity;
        prepared.cosInner = std::cos(glm::radians(light.spotInnerDeg));
        prepared.cosOuter = std::cos(glm::radians(light.spotOuterDeg));
        prepared.shadowed = light.castsShadow && shadowedCount < DERMIS_MAX_SHADOWED_LIGHTS;
        prepared.sinAngularRadius = std::sin(glm::radians(0.5f * light.angularDiameterDeg));
        prepared.radiusM = light.radiusM;
        if (prepared.shadowed) ++shadowedCount;
        mLights.push_back(prepared);
    }
}

float ReferenceLighting::energyLeftForDiffuse(float cosTheta, float roughness, float rhoS) const {
    // Texel centres on the sample points: coordinate = value x (size - 1).
    const float last = float(kEnergyTableSize - 1);
    const float x = std::clamp(cosTheta, 0.0f, 1.0f) * last;
    const float y = std::clamp(roughness, 0.0f, 1.0f) * last;
    const int x0 = std::min(static_cast<int>(x), kEnergyTableSize - 2);
    const int y0 = std::min(static_cast<int>(y), kEnergyTableSize - 2);
    const float fx = x - float(x0);
    const float fy = y - float(y0);
    auto at = [&](int i, int j) { return mEnergyTable[size_t(j) * kEnergyTableSize + size_t(i)]; };
    const float rhoDt = (1.0f - fy) * ((1.0f - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                        fy * ((1.0f - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    return std::clamp(1.0f - rhoS * rhoDt, 0.0f, 1.0f);
}

glm::vec3 ReferenceLighting::irradiance(const SurfacePoint& point, LightVisibility* visibility, uint32_t sampleSet) const {
    glm::vec3 e = mAmbient;
    const glm::vec3& n = point.shadingNormal;
    for (size_t i = 0; i < mLights.size(); ++i) {
        const PreparedLight& light = mLights[i];
        glm::vec3 l;
        glm::vec3 radiance = light.radiance;
        float rayLength = std::numeric_limits<float>::infinity();
        if (light.type == DERMIS_LIGHT_DIRECTIONAL) {
            l = -light.direction;
        } else {
            const glm::vec3 toLight = light.positionM - point.positionM;
            const float distanceSquaredM2 = std::max(glm::dot(toLight, toLight), 1e-6f);
            rayLength = std::sqrt(distanceSquaredM2);
            l = toLight / rayLength;
            radiance /= distanceSquaredM2;
            if (light.type == DERMIS_LIGHT_SPOT) {
                radiance *= smoothstep(light.cosOuter, light.cosInner, glm::dot(-l, light.direction));
            }
        }
        const float nDotL = glm::dot(n, l);
        if (!(nDotL > 0.0f)) continue;
        if (light.shadowed && i < 64) {
            const float visible = lightVisibility(i, point, l, rayLength, visibility);
            if (!(visible > 0.0f)) continue;
            radiance *= visible;
        }
        const float share = mEnergyConservation ? energyLeftForDiffuse(nDotL, point.roughness, point.rhoS) : 1.0f;
        e += radiance * (nDotL * share);
    }
    return e + environmentIrradiance(point, sampleSet);
}

glm::vec3 ReferenceLighting::environmentIrradiance(const SurfacePoint& point, uint32_t sampleSet) const {
    if (!hasEnvironment()) return glm::vec3(0.0f);
    const glm::vec3& n = point.shadingNormal;
    const float mapCount = float(mMapSquareSamples.size());
    const float cosineCount = float(mCosineSquareSamples.size());
    // One term of the multi-sample estimator with the power heuristic, exponent 2
    // (Veach 1997 eq. 9.12 with 9.15): for a direction drawn by technique t,
    //   w_t f / (n_t p_t) = f n_t p_t / ((n_map p_map)^2 + (n_cos p_cos)^2),
    // p_cos = max(N.omega, 0) / pi.
    auto term = [&](float cosTheta, const glm::vec3& radiance, float mapPdfPerSr, bool fromMap) {
        const float mapDensity = mapCount * mapPdfPerSr;
        const float cosineDensity = cosineCount * cosTheta * glm::one_over_pi<float>();
        const float density =
            (mapDensity * mapDensity + cosineDensity * cosineDensity) / (fromMap ? mapDensity : cosineDensity);
        const float share = mEnergyConservation ? energyLeftForDiffuse(cosTheta, point.roughness, point.rhoS) : 1.0f;
        return radiance * (cosTheta * share / density);
    };
    const uint32_t seed = positionSeed(point.positionM) ^ (sampleSet == 0 ? 0u : lowbias32(sampleSet * 0x85ebca6bu));
    const glm::vec2 mapShift(unitFromHash(lowbias32(seed + 1u)), unitFromHash(lowbias32(seed + 2u)));
    const glm::vec2 cosineShift(unitFromHash(lowbias32(seed + 3u)), unitFromHash(lowbias32(seed + 4u)));
    glm::vec3 t, b;
    tangentFrame(n, t, b);
    // In batches, each step over the whole batch before the next: the random look-ups into the
    // map and its CDFs miss the cache, and independent misses overlap. A cosine-drawn direction
    // is looked up only if its ray escapes (an occluded one contributes nothing).
    constexpr size_t kBatch = 16;
    std::array<EnvironmentSample, kBatch> batch;
    std::array<float, kBatch> cosines;
    std::array<bool, kBatch> lit;
    glm::dvec3 sum(0.0);
    const size_t mapSamples = mMapSquareSamples.size();
    const size_t total = mapSamples + mCosineSquareSamples.size();
    for (size_t first = 0; first < total; first += kBatch) {
        const size_t last = std::min(total, first + kBatch);
        for (size_t i = first; i < last; ++i) {
            EnvironmentSample& sample = batch[i - first];
            if (i < mapSamples) {
                sample = mEnvironment.sample(shiftedModuloOne(mMapSquareSamples[i], mapShift));
                sample.direction = mWorldFromMap * sample.direction;
                continue;
            }
            // Malley's method: a uniform disc point lifted onto the hemisphere is cosine-distributed
            // (Pharr, Jakob & Humphreys 2016 §13.6.3).
            const glm::vec2 u = shiftedModuloOne(mCosineSquareSamples[i - mapSamples], cosineShift);
            const glm::vec2 disc = raytrace::concentricDisc(u);
            const float up = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disc, disc)));
            sample.direction = glm::normalize(disc.x * t + disc.y * b + up * n);
        }
        for (size_t i = first; i < last; ++i) {
            const EnvironmentSample& sample = batch[i - first];
            const float cosTheta = glm::dot(n, sample.direction);
            cosines[i - first] = cosTheta;
            // A map-drawn direction towards a black texel has density 0 and was not drawn.
            const bool counts = cosTheta > 0.0f && (i >= mapSamples || sample.radiance != glm::vec3(0.0f));
            lit[i - first] =
                counts && !occluded(point, sample.direction, std::numeric_limits<float>::infinity());
        }
        for (size_t i = std::max(first, mapSamples); i < last; ++i) {
            EnvironmentSample& sample = batch[i - first];
            if (lit[i - first]) sample = mEnvironment.lookUp(glm::transpose(mWorldFromMap) * sample.direction);
        }
        for (size_t i = first; i < last; ++i) {
            const EnvironmentSample& sample = batch[i - first];
            if (!lit[i - first] || sample.radiance == glm::vec3(0.0f)) continue;
            sum += glm::dvec3(term(cosines[i - first], sample.radiance, sample.pdfPerSr, i < mapSamples));
        }
    }
    return glm::vec3(sum) * mEnvironmentIntensity;
}

float ReferenceLighting::lightVisibility(size_t index, const SurfacePoint& point, const glm::vec3& l, float distanceM,
                                         LightVisibility* visibility) const {
    const PreparedLight& light = mLights[index];
    // The light's angular radius seen from the point; a sphere around the point is a delta light.
    float sinRadius = light.sinAngularRadius;
    if (light.type != DERMIS_LIGHT_DIRECTIONAL) sinRadius = light.radiusM < distanceM ? light.radiusM / distanceM : 0.0f;
    const bool delta = !(sinRadius > 0.0f);
    const size_t rays = delta ? 1 : mDiscSamples.size();
    size_t unblocked = 0;
    for (size_t s = 0; s < rays; ++s) {
        const glm::vec3 direction = delta ? l : coneDirection(l, sinRadius, mDiscSamples[s]);
        float lengthM = distanceM;  // infinite for a directional light
        if (!delta && light.type != DERMIS_LIGHT_DIRECTIONAL) {
            // To the near side of the sphere along this direction.
            const float along = distanceM * glm::dot(direction, l);
            const float across2 = distanceM * distanceM - along * along;
            lengthM = along - std::sqrt(std::max(light.radiusM * light.radiusM - across2, 0.0f));
        } else if (light.type != DERMIS_LIGHT_DIRECTIONAL) {
            lengthM = distanceM - light.radiusM;
        }
        if (!occluded(point, direction, lengthM)) ++unblocked;
    }
    if (visibility) {
        const uint64_t bit = uint64_t(1) << index;
        visibility->tested |= bit;
        if (unblocked == rays) visibility->visible |= bit;
        if (unblocked == 0) visibility->blocked |= bit;
    }
    return float(unblocked) / float(rays);
}

// Near the terminator of a coarse mesh the interpolated normal can face the
// direction while the point's facet turns away from it. The smooth surface the
// mesh stands for lets such a ray out; the ray itself leaves under the facets
// and meets them first: its own facet or a neighbour from the front when
// Hanika's lift put the origin above them, a neighbour from the inside where
// the lift is too small to clear it (it goes to zero at the corners and is none
// in a hollow). On the head scan's shoulders, under the back spot light, the
// neighbours' inside faces blocked points 0.09 to 2 mm away, and nothing else
// lay towards the light (docs/reference.md, "Shadow rays on a coarse mesh").
// Such a ray passes under the point's own facets (its triangle and those that
// share a corner with it) once: in through their outside faces, out through
// their inside faces. Once it is out, whatever it meets is an occluder, its own
// facets too: a hollow that rises across the ray shadows the point.
bool ReferenceLighting::occluded(const SurfacePoint& point, const glm::vec3& direction, float lengthM) const {
    const Ray ray{rayOrigin(point, direction), direction};
    const bool underTheFacets =
        glm::dot(point.smoothNormal, direction) >= 0.0f && glm::dot(point.geometricNormal, direction) < 0.0f;
    const uint32_t own = point.tracedTriangle;
    if (!underTheFacets || own >= mOccluders->triangleCount()) return mOccluders->anyHit(ray, 0.0f, lengthM);
    const std::array<glm::vec3, 3> corners{mOccluders->corner(own, 0), mOccluders->corner(own, 1), mOccluders->corner(own, 2)};
    auto ownFacet = [&](uint32_t triangle) {
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 c = mOccluders->corner(triangle, k);
            if (c == corners[0] || c == corners[1] || c == corners[2]) return true;
        }
        return false;
    };
    // A ray under the facets crosses one to three of them (measured on the scan
    // and on a coarse saddle); one still among them after this many is taken as blocked.
    constexpr int kMaxFacetsPassed = 8;
    float tMin = 0.0f;
    for (int passed = 0; passed < kMaxFacetsPassed; ++passed) {
        raytrace::BvhHit hit;
        if (!mOccluders->closestHit(ray, tMin, lengthM, &hit)) return false;
        if (!ownFacet(hit.triangle)) return true;
        if (hit.backFace) return mOccluders->anyHit(ray, hit.t, lengthM);  // out from under the facets
        tMin = hit.t;
    }
    return true;
}

float ReferenceLighting::outgoingFactor(const SurfacePoint& point, const glm::vec3& towardsViewer) const {
    if (!mEnergyConservation) return 1.0f;
    return energyLeftForDiffuse(std::clamp(glm::dot(point.shadingNormal, towardsViewer), 0.0f, 1.0f), point.roughness,
                                point.rhoS);
}

}  // namespace dermis::reference
