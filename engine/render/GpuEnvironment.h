#pragma once
// The GPU side of the environment light (plan/EnvironmentPlan.h,
// docs/environment.md), owned by the frame resources and made in the prepare
// step (a GL context must be current):
//   - the EnvironmentBlock (binding DERMIS_BINDING_ENVIRONMENT) each frame;
//   - the map with its prefiltered mips (env/PrefilteredEnvironment.h) on unit
//     DERMIS_UNIT_ENVIRONMENT, made again only when the source changes: made
//     from what is left when a dominant light was taken out (the light itself
//     is a scene light of the frame), so that the specular does not count it
//     twice; the skybox shows the whole map (background());
//   - the diffuse irradiance of the same (env/IrradianceMap.h) on unit
//     DERMIS_UNIT_ENVIRONMENT_IRRADIANCE, made with it;
//   - each character's per-vertex SH transfer (env/ShTransferCache.h: computed
//     once, then read from the disk cache), a vertex buffer attached to its
//     vertex arrays at DERMIS_LOCATION_TRANSFER, only when the occlusion is
//     "transfer". An animated character has a second, posed buffer that the
//     skinning pass fills by turning the rest pose's transfer with each
//     vertex's skinning (shaders/transfer_rotate.comp); that one is attached.

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "gpu/UniformBlocks.h"
#include "mesh/Mesh.h"
#include "plan/EnvironmentPlan.h"

#include "env/ShTransfer.h"

#include <memory>
#include <vector>

namespace dermis {

class GpuEnvironment {
public:
    GpuEnvironment();

    // Uploads the block, and the map when its source changed. Binds both.
    void prepare(const EnvironmentPlan& plan, const Scene& scene);
    // The character's transfer buffers, made on first need (0 before): the
    // rest pose's, and for an animated character the posed one. They hold the
    // visible share of the plan's map (env/ShTransfer.h visibleShareTransfer)
    // for the character's rotation `worldFromObject`, made again when the map
    // or that rotation changes; an animated character keeps the share it was
    // first drawn with (the skinning pass turns it with the pose).
    Status prepareTransfer(size_t character, const MeshData& mesh, bool animated, const EnvironmentPlan& plan,
                           const glm::mat3& worldFromObject);
    GLuint restTransfer(size_t character) const {
        return character < mTransfers.size() ? mTransfers[character].rest.get() : 0;
    }
    GLuint posedTransfer(size_t character) const {
        return character < mTransfers.size() ? mTransfers[character].posed.get() : 0;
    }
    // What the character's vertex arrays read: the posed buffer if any, else the rest pose's.
    GLuint drawnTransfer(size_t character) const {
        return posedTransfer(character) != 0 ? posedTransfer(character) : restTransfer(character);
    }
    // The map as loaded, for the skybox: the prefiltered chain's level 0
    // unless a light was taken out of it, else a copy of the whole map at that size.
    GLuint background() const { return mBackground.isValid() ? mBackground.get() : mMap.get(); }
    // Attaches a transfer buffer (three vec3 per vertex) to a vertex array.
    static void attachTransfer(GLuint vertexArray, GLuint buffer);

private:
    gl::Buffer mUniforms;
    gl::Texture mMap;
    gl::Texture mIrradiance;  // env/IrradianceMap.h, at DERMIS_UNIT_ENVIRONMENT_IRRADIANCE
    gl::Texture mBackground;  // only when the map lit is not the map shown
    ShareLight mShareLight;   // the lit map by area at kShareMapWidth and its hot directions, for visibleShareTransfer
    std::shared_ptr<const EnvironmentLight> mMapLight;  // what mMap was made from
    int mMapLevels = 0;
    struct Transfer {
        gl::Buffer rest;
        gl::Buffer posed;  // animated characters only
        ShTransfer traced;  // the SH transfer and each ray's visibility (env/ShTransferCache.h)
        const EnvironmentLight* light = nullptr;  // what rest holds the share of
        glm::mat3 mapFromObject{0.0f};
        const MeshData* mesh = nullptr;           // characters that share a model share the share
        std::vector<ShScalar9> uploaded;
    };
    std::vector<Transfer> mTransfers;
    std::vector<float> mAverageAlbedo;  // DERMIS_AVERAGE_ALBEDO_SIZE values of m
    std::vector<glm::vec4> mRhoDtFits;  // DERMIS_AVERAGE_ALBEDO_SIZE cubics, one per m
};

// rho_dt(mu, m) averaged over the cosine-weighted hemisphere, 2 int_0^1
// rho_dt(mu, m) mu dmu, from the energy table (row-major, row = m; brdf/EnergyTable.h),
// by the trapezoid rule over its columns, one value per row.
std::vector<float> hemisphericalAverageAlbedo(const std::vector<float>& energyTable, int size);

// Per row m of the energy table, the cubic c0 + c1 mu + c2 mu^2 + c3 mu^3
// closest to rho_dt(mu, m) by least squares weighted by mu (the cosine that
// multiplies it in the diffuse light; trapezoids over the table's columns).
// With the irradiance map's cosine powers E_k (env/IrradianceMap.h) the
// diffuse light a specular lobe leaves is
//   sum L max(cos, 0) (1 - rho_s rho_dt(cos)) dw = E_1 - rho_s sum_k c_k E_(k+1),
// the energy conservation per direction that the CPU reference applies.
// The weighted mean 2 int c(mu) mu dmu equals hemisphericalAverageAlbedo's,
// since the constant is one of the fitted functions: under a uniform map
// the two agree (the white furnace).
std::vector<glm::vec4> rhoDtCubicFits(const std::vector<float>& energyTable, int size);

}  // namespace dermis
