#pragma once
// Per-vertex spherical-harmonic transfer for environment light: how much of
// the environment a vertex sees past the character's own mesh, weighted by
// the cosine (Sloan et al. 2002; per vertex as in Chappuis 2011 §3.3 and
// Yang et al. 2012 §III):
//
//   T_lm(vertex) = integral over the sphere of V(w) max(N . w, 0) Y_lm(w) dw
//
// with N the vertex normal and V(w) = 0 where a ray from the vertex towards w
// hits the mesh. Lit by an environment whose SH radiance is L (in the mesh's
// object space), the vertex's irradiance is E = sum_lm L_lm T_lm. With no
// occluder, T_lm = A_l Y_lm(N) (Funk-Hecke; the A_l of shIrradiance).
//
// Estimated with cosine-weighted rays (pdf = N . w / pi), so
//   T_lm ~= (pi / n) sum_i V(w_i) Y_lm(w_i):
// a jittered sqrt(n) x sqrt(n) grid on the unit square, mapped to the disc
// by the concentric map (Shirley & Chiu 1997) and lifted to the hemisphere
// (Malley's method), turned about the normal by an angle hashed from the
// vertex index. Every random number comes from the vertex and sample index,
// so the result is the same for any thread count.

#include "core/Image.h"
#include "core/Result.h"
#include "env/SphericalHarmonics.h"
#include "mesh/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

// 256 rays (16 x 16 strata): the RMS error of T_00 on the occluded test case
// (a vertex beside a wall) is about 0.2% of the unoccluded T_00, and the time
// for a 10k-vertex head stays well under 10 s on two cores; see
// docs/environment.md for the measurements.
constexpr int kDefaultShTransferRays = 256;

struct ShTransferOptions {
    int raysPerVertex = kDefaultShTransferRays;  // a square number (the strata are a square grid)
    int threads = 0;                             // 0: all hardware threads
    std::string progressLabel = "SH transfer";   // empty: no progress bar
};

// One transfer vector per vertex, in the mesh's vertex order; which of the
// vertex's rays escaped: visibilityWords(raysPerVertex) words per vertex, bit
// i of the ray forEachTransferRay gives as i; and which vertices lie inside
// the body (buried: more than half of their rays meet the inside of a surface
// first, as from the skull under an ear whose root is sunk into it). A buried
// vertex is no surface the light reaches: its transfer is its neighbours'
// (fillBuriedFromNeighbours), so that a triangle that passes into the body
// takes the light of its part outside, not a fade to black from its buried
// corner (docs/environment.md, "Vertices inside the body").
struct ShTransfer {
    std::vector<ShScalar9> perVertex;
    std::vector<uint32_t> visibility;
    std::vector<uint8_t> buried;
    int raysPerVertex = 0;
};

inline size_t visibilityWords(int raysPerVertex) { return (size_t(raysPerVertex) + 31) / 32; }

// The mesh's own occlusion only. Errors: raysPerVertex not a positive
// square, an index outside the vertex list, an index count that is not a
// multiple of 3.
Result<ShTransfer> computeShTransfer(const MeshData& mesh, const ShTransferOptions& options = {});

// Which vertices lie inside the body, by the rule computeShTransfer uses
// (more than half of the vertex's raysPerVertex cosine-weighted rays meet the
// inside of a surface first), without the transfer. For texture space, whose
// irradiance texture leaves out the surface no light reaches
// (plan/SceneGeometry.h). Errors as computeShTransfer's.
Result<std::vector<uint8_t>> findBuriedVertices(const MeshData& mesh, int raysPerVertex);

// The transfer of a vertex that has turned by `rotation` (object space, bind
// pose -> posed): rotated(w) = transfer(rotation^T w), so E = L . T stays the
// irradiance with L in the same object space as the posed vertex. Exact for
// a rigid motion of the whole mesh; for a skinned vertex it keeps the bind
// pose's occlusion, turned with the vertex (docs/environment.md measures the
// error).
ShScalar9 rotateTransfer(const ShScalar9& transfer, const glm::mat3& rotation);

// The transfer for one map, with the occlusion exact instead of band-limited
// (docs/environment.md, "The visible share"): per vertex
//   s = sum_i V_i L(w_i) / sum_i L(w_i)
// over the vertex's own cosine-weighted rays (their escapes recorded in
// transfer.visibility), L the luminance of `lit` (the map the diffuse light is
// made from) looked up in the direction mapFromObject w_i, and the result is
// s times the unoccluded transfer A_l Y_lm(N). Lit by the same map, L . T is
// then s times the vertex's unoccluded irradiance: nine coefficients carry
// the whole occlusion of that map, where the SH transfer spreads an
// occluder's shadow over directions it does not hide. Returns the transfer
// unchanged when it holds no visibility.
//
// A sun left in the map (extract_light off, or a second sun) is a few texels
// that 256 rays a vertex meet by chance: the share jumped from vertex to
// vertex, dark blotches on a face. So the map's hot part (its texels' power
// above the cap of env/RingingFreeSh.h) is kept apart, `hot`, one direction
// per share-map texel, and each is weighed at every vertex by its cosine and
// its visibility: the mean escape of the vertex's rays within
// kHotVisibilityConeDeg of it (the nearest ray's where none is):
//   s = (pi/n sum_i V_i L(w_i) + sum_h V_h P_h max(N . h, 0))
//     / (pi/n sum_i L(w_i)     + sum_h P_h max(N . h, 0))
// with `lit` the map without them and P_h their luminance x solid angle.
struct HotDirection {
    glm::vec3 directionMap{0.0f, 1.0f, 0.0f};  // unit, in the map's space
    float power = 0.0f;                        // luminance x solid angle
};
std::vector<ShScalar9> visibleShareTransfer(const MeshData& mesh, const ShTransfer& transfer, const Image& lit,
                                            const glm::mat3& mapFromObject, const std::vector<HotDirection>& hot = {});

// The rays' half-angle over which a hot direction's visibility is averaged:
// the 256 rays lie about 9 degrees apart, so about 6 rays fall in it near
// the normal and the shadow's edge is softened by as much.
constexpr float kHotVisibilityConeDeg = 15.0f;
// The most hot directions weighed apart (the brightest); the others stay in
// the map the rays read.
constexpr int kMaxHotDirections = 32;

// A lit map split for visibleShareTransfer at width x width / 2: the map its
// rays read (the smooth part, plus any hot part beyond the kMaxHotDirections
// brightest) and the hot directions.
struct ShareLight {
    Image smooth;
    std::vector<HotDirection> hot;
};
ShareLight shareLightOf(const Image& lit, int width);

// Each buried vertex (buried[v] != 0) takes the mean of its neighbours'
// values (vertices that share a triangle with it) that are not buried, or
// were filled in an earlier round: rounds grow the filled region inward from
// the outside surface until nothing changes. A part wholly inside the body
// keeps its values.
void fillBuriedFromNeighbours(const MeshData& mesh, const std::vector<uint8_t>& buried, std::vector<ShScalar9>& values);

// The rotation of a linear-blend skinning matrix: the orthonormal factor of
// its upper 3 x 3's polar decomposition (the closest rotation to it; Higham
// 1986: the iteration X <- (X + X^-T) / 2). A blend of rotations is not a
// rotation; its polar factor is what a vertex's frame turns by.
glm::mat3 skinningRotation(const glm::mat4& blendedSkinningMatrix);

}  // namespace dermis
