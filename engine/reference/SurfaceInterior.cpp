#include "reference/SurfaceInterior.h"

#include "mesh/MeshTopology.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <utility>

namespace dermis::reference {
namespace {

// Three directions that meet no axis-aligned edge or face of a mesh squarely.
constexpr std::array<glm::vec3, 3> kParityDirections = {glm::vec3(0.5773f, 0.5780f, 0.5767f),
                                                        glm::vec3(-0.6123f, 0.3481f, 0.7098f),
                                                        glm::vec3(0.2107f, -0.8944f, 0.3946f)};
// Crossings beyond this many are counted no further (a ray through a
// pathological mesh); the parity is then taken as it stands.
constexpr int kMaxCrossings = 256;

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
}

}  // namespace

SurfaceInterior SurfaceInterior::build(const CharacterSurface& surface) {
    SurfaceInterior interior;
    interior.mSurface = &surface;
    const size_t triangles = surface.triangleCount();
    interior.mStates.assign(triangles, State::Outside);
    std::vector<glm::vec3> corners;
    corners.reserve(3 * triangles);
    for (size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k) corners.push_back(surface.corner(t, k));
    const WeldedPoints welded = weldByPosition(corners);

    // Parts: triangles joined through welded corners.
    std::vector<uint32_t> parent(welded.count);
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t a = findRoot(parent, welded.ids[3 * t]);
        for (int k = 1; k < 3; ++k) {
            const uint32_t b = findRoot(parent, welded.ids[3 * t + size_t(k)]);
            if (a != b) parent[b] = a;
        }
    }
    std::map<uint32_t, uint32_t> partOfRoot;
    interior.mPartOfTriangle.resize(triangles);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t root = findRoot(parent, welded.ids[3 * t]);
        interior.mPartOfTriangle[t] = partOfRoot.emplace(root, uint32_t(partOfRoot.size())).first->second;
    }
    const size_t parts = partOfRoot.size();

    // Closed parts: every welded edge used by exactly two of the part's triangles.
    std::map<std::pair<uint32_t, uint32_t>, int> edgeUses;
    for (size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = welded.ids[3 * t + size_t(k)], b = welded.ids[3 * t + size_t((k + 1) % 3)];
            ++edgeUses[{std::min(a, b), std::max(a, b)}];
        }
    }
    interior.mPartClosed.assign(parts, 1);
    for (size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = welded.ids[3 * t + size_t(k)], b = welded.ids[3 * t + size_t((k + 1) % 3)];
            if (edgeUses[{std::min(a, b), std::max(a, b)}] != 2) interior.mPartClosed[interior.mPartOfTriangle[t]] = 0;
        }
    }
    if (parts < 2 || interior.closedPartCount() == 0) return interior;  // nothing can be inside anything

    interior.mPartMinM.assign(parts, glm::vec3(INFINITY));
    interior.mPartMaxM.assign(parts, glm::vec3(-INFINITY));
    for (size_t i = 0; i < corners.size(); ++i) {
        const uint32_t part = interior.mPartOfTriangle[i / 3];
        interior.mPartMinM[part] = glm::min(interior.mPartMinM[part], corners[i]);
        interior.mPartMaxM[part] = glm::max(interior.mPartMaxM[part], corners[i]);
    }
    interior.mAll = std::make_shared<const raytrace::Bvh>(raytrace::Bvh::build(corners));

    // Two triangles of different parts cross where an edge of one passes through
    // the other: both are tested point by point.
    std::vector<uint8_t> crossed(triangles, 0);
    for (size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 from = corners[3 * t + size_t(k)], to = corners[3 * t + size_t((k + 1) % 3)];
            const float length = glm::length(to - from);
            if (!(length > 0.0f)) continue;
            const raytrace::Ray edge{from, (to - from) / length};
            float tMin = 1e-6f * length;
            raytrace::BvhHit hit;
            for (int step = 0; step < kMaxCrossings && interior.mAll->closestHit(edge, tMin, length * (1.0f - 1e-6f), &hit);
                 ++step) {
                if (interior.mPartOfTriangle[hit.triangle] != interior.mPartOfTriangle[t]) crossed[t] = crossed[hit.triangle] = 1;
                tMin = hit.t;
            }
        }
    }
    // Every other triangle lies wholly inside or wholly outside: its centroid says which.
    for (size_t t = 0; t < triangles; ++t) {
        if (crossed[t]) {
            interior.mStates[t] = State::Straddling;
            continue;
        }
        const glm::vec3 centroid = (corners[3 * t] + corners[3 * t + 1] + corners[3 * t + 2]) / 3.0f;
        interior.mStates[t] = interior.insideAnotherPart(centroid, interior.mPartOfTriangle[t]) ? State::Inside : State::Outside;
    }
    return interior;
}

bool SurfaceInterior::insideAnotherPart(const glm::vec3& pointM, uint32_t ownPart) const {
    if (!mAll) return false;
    bool anyBounds = false;
    for (size_t part = 0; part < mPartClosed.size(); ++part) {
        if (part == ownPart || !mPartClosed[part]) continue;
        anyBounds = anyBounds || (glm::all(glm::greaterThanEqual(pointM, mPartMinM[part])) &&
                                  glm::all(glm::lessThanEqual(pointM, mPartMaxM[part])));
    }
    if (!anyBounds) return false;
    int votes = 0;
    std::vector<uint8_t> parity(mPartClosed.size());
    for (const glm::vec3& direction : kParityDirections) {
        std::fill(parity.begin(), parity.end(), uint8_t(0));
        float tMin = 0.0f;
        raytrace::BvhHit hit;
        for (int crossing = 0; crossing < kMaxCrossings && mAll->closestHit({pointM, direction}, tMin, INFINITY, &hit);
             ++crossing) {
            parity[mPartOfTriangle[hit.triangle]] ^= 1u;
            tMin = hit.t;
        }
        bool inside = false;
        for (size_t part = 0; part < parity.size(); ++part)
            inside = inside || (part != ownPart && mPartClosed[part] && parity[part]);
        votes += inside ? 1 : 0;
    }
    return votes >= 2;
}

bool SurfaceInterior::buried(size_t triangle, float b1, float b2) const {
    switch (mStates.empty() ? State::Outside : mStates[triangle]) {
        case State::Outside: return false;
        case State::Inside: return true;
        case State::Straddling: break;
    }
    return insideAnotherPart(mSurface->positionAt(triangle, b1, b2), mPartOfTriangle[triangle]);
}

size_t SurfaceInterior::closedPartCount() const {
    return size_t(std::count(mPartClosed.begin(), mPartClosed.end(), uint8_t(1)));
}

size_t SurfaceInterior::buriedTriangleCount() const {
    return size_t(std::count(mStates.begin(), mStates.end(), State::Inside));
}

size_t SurfaceInterior::straddlingTriangleCount() const {
    return size_t(std::count(mStates.begin(), mStates.end(), State::Straddling));
}

}  // namespace dermis::reference
