#pragma once
// The parts of a character's surface that lie inside its own body.
//
// A mesh made of closed parts that pass into one another (the procedural
// head's ears are closed plates whose roots are sunk into the closed skull)
// has surface inside the body: the ear's root within the skull, the skull
// under the ear. That surface is no boundary between skin and air: no light
// enters there, and light that scatters past it stays in the tissue. The
// subsurface integral (DiffusionIntegrator) takes its donors from the
// boundary only, so it leaves these points out; with them, a point beside
// the junction gathered light from both parts' full surfaces and took twice
// a flat surface's share of the profile (docs/reference.md, "Surface inside
// the body").
//
// A point is inside the body when it lies inside a closed part (every edge,
// with the vertices at one position welded, shared by exactly two triangles)
// other than its own: an odd number of that part's triangles along a ray,
// the majority of three rays. Open parts enclose nothing that a ray could
// count, so they never bury anything.

#include "reference/CharacterSurface.h"
#include "raytrace/Bvh.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace dermis::reference {

class SurfaceInterior {
public:
    static SurfaceInterior build(const CharacterSurface& surface);

    // Whether the point at barycentric weights (b1, b2) of `triangle` lies inside the body.
    bool buried(size_t triangle, float b1, float b2) const;

    size_t partCount() const { return mPartClosed.size(); }
    size_t closedPartCount() const;
    size_t buriedTriangleCount() const;      // wholly inside the body
    size_t straddlingTriangleCount() const;  // crossed by another part: tested point by point

private:
    enum class State : uint8_t { Outside, Inside, Straddling };
    bool insideAnotherPart(const glm::vec3& pointM, uint32_t ownPart) const;

    const CharacterSurface* mSurface = nullptr;
    std::vector<uint32_t> mPartOfTriangle;
    std::vector<uint8_t> mPartClosed;
    std::vector<State> mStates;                    // per triangle
    std::shared_ptr<const raytrace::Bvh> mAll;   // every triangle, in the surface's order
    std::vector<glm::vec3> mPartMinM, mPartMaxM;  // each part's bounds
};

}  // namespace dermis::reference
