#include "raytrace/EmbreeBvh.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace dermis::raytrace {
namespace {

RTCDevice device(void* handle) { return static_cast<RTCDevice>(handle); }
RTCScene scene(void* handle) { return static_cast<RTCScene>(handle); }

// std::nextafter(t, +-infinity), inline: it is called twice per ray, and libm's call cost
// 4 % of a reference under an environment map.
float nextFloat(float t, bool up) {
    if (std::isnan(t) || (std::isinf(t) && (t > 0.0f) == up)) return t;
    if (t == 0.0f) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
    uint32_t bits = 0;
    std::memcpy(&bits, &t, sizeof bits);
    bits = (t > 0.0f) == up ? bits + 1u : bits - 1u;  // the magnitude grows or shrinks by one ulp
    std::memcpy(&t, &bits, sizeof bits);
    return t;
}
// The next float towards +infinity: Embree accepts t in [tnear, tfar], Bvh only tMin < t < tMax.
float above(float t) { return nextFloat(t, true); }
float below(float t) { return nextFloat(t, false); }

// Embree's ray for tMin < t < tMax.
RTCRay embreeRay(const Ray& ray, float tMin, float tMax) {
    RTCRay out{};
    out.org_x = ray.origin.x;
    out.org_y = ray.origin.y;
    out.org_z = ray.origin.z;
    out.dir_x = ray.direction.x;
    out.dir_y = ray.direction.y;
    out.dir_z = ray.direction.z;
    out.tnear = above(tMin);
    out.tfar = below(tMax);
    out.mask = 0xFFFFFFFFu;
    return out;
}

}  // namespace

EmbreeBvh EmbreeBvh::build(const std::vector<glm::vec3>& cornersM) {
    EmbreeBvh bvh;
    // "threads=1": Embree's own build threads would compete with the callers' loops;
    // the build is a small share of a reference (docs/reference.md).
    bvh.mDevice = rtcNewDevice("threads=1");
    if (!bvh.mDevice) throw std::runtime_error("Embree: rtcNewDevice failed");
    bvh.mScene = rtcNewScene(device(bvh.mDevice));
    rtcSetSceneFlags(scene(bvh.mScene), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene(bvh.mScene), RTC_BUILD_QUALITY_HIGH);
    bvh.mTriangleCount = cornersM.size() / 3;
    bvh.mCornersM.assign(cornersM.begin(), cornersM.begin() + std::ptrdiff_t(3 * bvh.mTriangleCount));
    if (bvh.mTriangleCount > 0) {
        RTCGeometry geometry = rtcNewGeometry(device(bvh.mDevice), RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                     RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                     3 * bvh.mTriangleCount));
        auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                       RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
                                                                       bvh.mTriangleCount));
        for (size_t i = 0; i < 3 * bvh.mTriangleCount; ++i) {
            for (int axis = 0; axis < 3; ++axis) vertices[3 * i + size_t(axis)] = cornersM[i][axis];
            indices[i] = static_cast<uint32_t>(i);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene(bvh.mScene), geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene(bvh.mScene));
    return bvh;
}

EmbreeBvh::EmbreeBvh(EmbreeBvh&& other) noexcept
    : TriangleScene(std::move(other)),
      mDevice(std::exchange(other.mDevice, nullptr)),
      mScene(std::exchange(other.mScene, nullptr)),
      mTriangleCount(other.mTriangleCount) {}

EmbreeBvh& EmbreeBvh::operator=(EmbreeBvh&& other) noexcept {
    if (this != &other) {
        release();
        TriangleScene::operator=(std::move(other));
        mDevice = std::exchange(other.mDevice, nullptr);
        mScene = std::exchange(other.mScene, nullptr);
        mTriangleCount = other.mTriangleCount;
    }
    return *this;
}

EmbreeBvh::~EmbreeBvh() { release(); }

void EmbreeBvh::release() {
    if (mScene) rtcReleaseScene(scene(mScene));
    if (mDevice) rtcReleaseDevice(device(mDevice));
    mScene = nullptr;
    mDevice = nullptr;
}

bool EmbreeBvh::closestHit(const Ray& ray, float tMin, float tMax, BvhHit* hit) const {
    if (!(tMin < tMax) || mTriangleCount == 0) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = embreeRay(ray, tMin, tMax);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene(mScene), &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    // Embree's geometry normal is the counter-clockwise one, cross(v1 - v0, v2 - v0), unnormalised.
    const float alongNormal =
        query.hit.Ng_x * query.ray.dir_x + query.hit.Ng_y * query.ray.dir_y + query.hit.Ng_z * query.ray.dir_z;
    *hit = BvhHit{query.ray.tfar, query.hit.primID, query.hit.u, query.hit.v, alongNormal > 0.0f};
    return true;
}

bool EmbreeBvh::anyHit(const Ray& ray, float tMin, float tMax) const {
    if (!(tMin < tMax) || mTriangleCount == 0) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay query = embreeRay(ray, tMin, tMax);
    rtcOccluded1(scene(mScene), &context, &query);
    return query.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace dermis::raytrace
