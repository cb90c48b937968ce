#include "render/GpuEnvironment.h"

#include "brdf/EnergyTable.h"
#include "env/IrradianceMap.h"
#include "env/PrefilteredEnvironment.h"
#include "env/ShTransferCache.h"
#include "core/Log.h"
#include "gl/TexturePool.h"

#include <algorithm>
#include <cstddef>

namespace dermis {
namespace {

// The visible share reads the lit map at this width (by area): 256 rays per
// vertex meet texels of 2.8 degrees, so a small bright texel adds no more
// noise to the share than to the rays' own sampling.
constexpr int kShareMapWidth = 128;

// An RGBA lat-long texture of `levels` (level 0 first), u repeating, v clamped, trilinear.
gl::Texture uploadLatLong(const std::vector<Image>& levels, std::string_view label,
                          graph::TextureFormat format = graph::TextureFormat::Rgba16F) {
    gl::Texture texture = gl::createTexture2D({static_cast<uint32_t>(levels.front().width),
                                               static_cast<uint32_t>(levels.front().height), format},
                                              label, static_cast<int>(levels.size()));
    for (size_t level = 0; level < levels.size(); ++level) {
        glTextureSubImage2D(texture.get(), static_cast<GLint>(level), 0, 0, levels[level].width, levels[level].height,
                            GL_RGBA, GL_FLOAT, levels[level].texels.data());
    }
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

// Lat-long maps of one size stacked down one RGBA32F texture, each between
// copies of its first and last rows, so that a bilinear read inside one never
// reaches the next (the v clamp of a texture of its own); u repeats
// (shaders/include/Environment.glsl, irradiancePower).
gl::Texture uploadStackedLatLong(const std::vector<Image>& maps, std::string_view label) {
    Image stacked;
    stacked.width = maps.front().width;
    stacked.height = (maps.front().height + 2) * int(maps.size());
    stacked.texels.reserve(size_t(stacked.width) * size_t(stacked.height));
    for (const Image& map : maps) {
        for (int row = -1; row <= map.height; ++row) {
            const int source = std::clamp(row, 0, map.height - 1);
            stacked.texels.insert(stacked.texels.end(), map.texels.begin() + ptrdiff_t(source) * map.width,
                                  map.texels.begin() + ptrdiff_t(source + 1) * map.width);
        }
    }
    return uploadLatLong({stacked}, label, graph::TextureFormat::Rgba32F);
}

}  // namespace

static_assert(DERMIS_AVERAGE_ALBEDO_SIZE == kEnergyTableSize, "one average per energy-table row");
static_assert(DERMIS_IRRADIANCE_POWERS == kIrradiancePowers && kIrradiancePowers == glm::vec4::length(),
              "the shaders read one stacked cosine power per coefficient of rho_dt's cubic");
static_assert(sizeof(ShScalar9) == DERMIS_SH_COEFFICIENTS * sizeof(float), "three vec3 attributes per vertex");

std::vector<float> hemisphericalAverageAlbedo(const std::vector<float>& energyTable, int size) {
    std::vector<float> average(size_t(size), 0.0f);
    for (int row = 0; row < size; ++row) {
        double sum = 0.0;
        for (int column = 0; column + 1 < size; ++column) {
            const double mu0 = double(column) / (size - 1), mu1 = double(column + 1) / (size - 1);
            const double f0 = energyTable[size_t(row * size + column)] * mu0;
            const double f1 = energyTable[size_t(row * size + column + 1)] * mu1;
            sum += 0.5 * (f0 + f1) * (mu1 - mu0);
        }
        average[size_t(row)] = float(2.0 * sum);
    }
    return average;
}

std::vector<glm::vec4> rhoDtCubicFits(const std::vector<float>& energyTable, int size) {
    std::vector<glm::vec4> fits(size_t(size), glm::vec4(0.0f));
    for (int row = 0; row < size; ++row) {
        glm::dmat4 normal(0.0);  // sum w p p^T
        glm::dvec4 right(0.0);   // sum w p rho
        for (int column = 0; column < size; ++column) {
            const double mu = double(column) / (size - 1);
            const double trapezoid = (column == 0 || column == size - 1 ? 0.5 : 1.0) / (size - 1);
            const double weight = mu * trapezoid;
            const glm::dvec4 powers(1.0, mu, mu * mu, mu * mu * mu);
            normal += weight * glm::outerProduct(powers, powers);
            right += weight * powers * double(energyTable[size_t(row * size + column)]);
        }
        fits[size_t(row)] = glm::vec4(glm::inverse(normal) * right);
    }
    return fits;
}

GpuEnvironment::GpuEnvironment() {
    mUniforms = gl::createBuffer("environment: EnvironmentBlock");
    glNamedBufferStorage(mUniforms.get(), sizeof(gpu::EnvironmentBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    const std::vector<float> energyTable = makeEnergyTable(kEnergyTableSize);
    mAverageAlbedo = hemisphericalAverageAlbedo(energyTable, kEnergyTableSize);
    mRhoDtFits = rhoDtCubicFits(energyTable, kEnergyTableSize);
}

void GpuEnvironment::prepare(const EnvironmentPlan& plan, const Scene& scene) {
    gpu::EnvironmentBlock block{};
    if (plan.enabled()) {
        if (mMapLight != plan.light) {
            const PrefilteredEnvironment prefiltered = PrefilteredEnvironment::build(plan.light->lit());
            mMap = uploadLatLong(prefiltered.levels(), "environment: prefiltered map");
            mMapLevels = static_cast<int>(prefiltered.levels().size());
            mIrradiance = uploadStackedLatLong(plan.light->irradiancePowers, "environment: irradiance map and cosine powers");
            mShareLight = shareLightOf(plan.light->lit(), kShareMapWidth);
            const Image& base = prefiltered.levels().front();
            mBackground = plan.light->extracted.empty()
                              ? gl::Texture()
                              : uploadLatLong({resampleLatLongByArea(plan.light->map, base.width, base.height)},
                                              "environment: background (with its extracted light)");
            mMapLight = plan.light;
        }
        const Environment& environment = scene.environment;
        for (int i = 0; i < kShCoefficients; ++i) {
            block.sh[i] = glm::vec4(plan.worldSh.coefficients[size_t(i)], 0.0f);
            block.hotSh[i] = glm::vec4(plan.worldHotSh.coefficients[size_t(i)], 0.0f);
        }
        block.mapFromWorld = glm::mat4(glm::transpose(plan.worldFromMap));
        block.lit = 1.0f;
        block.occlusion = float(int(environment.occlusion));
        block.specularMode = float(int(environment.specular));
        block.intensity = environment.intensity;
        block.lastMipLevel = float(mMapLevels - 1);
        block.skybox = plan.skybox ? 1.0f : 0.0f;
        block.diffuseMode = float(int(environment.diffuse));
        for (size_t i = 0; i < mAverageAlbedo.size(); ++i) block.averageAlbedo[i / 4][int(i % 4)] = mAverageAlbedo[i];
        for (size_t i = 0; i < mRhoDtFits.size(); ++i) block.rhoDtFits[i] = mRhoDtFits[i];
    }
    glNamedBufferSubData(mUniforms.get(), 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_ENVIRONMENT, mUniforms.get());
    glBindTextureUnit(DERMIS_UNIT_ENVIRONMENT, mMap.get());
    glBindTextureUnit(DERMIS_UNIT_ENVIRONMENT_IRRADIANCE, mIrradiance.get());
}

Status GpuEnvironment::prepareTransfer(size_t character, const MeshData& mesh, bool animated, const EnvironmentPlan& plan,
                                       const glm::mat3& worldFromObject) {
    if (mTransfers.size() <= character) mTransfers.resize(character + 1);
    Transfer& transfer = mTransfers[character];
    if (transfer.traced.perVertex.empty()) {
        auto loaded = loadOrComputeShTransfer(mesh);
        if (!loaded.ok()) return loaded.error();
        transfer.traced = std::move(loaded->transfer);
    }
    // The rotation part of the character's transform (its columns' lengths are the scale).
    glm::mat3 objectRotation = worldFromObject;
    for (int c = 0; c < 3; ++c) objectRotation[c] = glm::normalize(objectRotation[c]);
    const glm::mat3 mapFromObject = glm::transpose(plan.worldFromMap) * objectRotation;
    const EnvironmentLight* light = plan.light.get();
    const bool current = transfer.rest.isValid() && light == transfer.light && mapFromObject == transfer.mapFromObject;
    if (current || (transfer.rest.isValid() && animated)) return success();

    const Transfer* same = nullptr;
    for (const Transfer& other : mTransfers)
        if (&other != &transfer && other.mesh == &mesh && other.light == light && other.mapFromObject == mapFromObject &&
            !other.uploaded.empty())
            same = &other;
    transfer.uploaded = same ? same->uploaded
                        : light ? visibleShareTransfer(mesh, transfer.traced, mShareLight.smooth, mapFromObject, mShareLight.hot)
                                : transfer.traced.perVertex;
    transfer.light = light;
    transfer.mapFromObject = mapFromObject;
    transfer.mesh = &mesh;
    const std::vector<ShScalar9>& perVertex = transfer.uploaded;
    const auto bytes = static_cast<GLsizeiptr>(perVertex.size() * sizeof(ShScalar9));
    if (transfer.rest.isValid()) {
        glNamedBufferSubData(transfer.rest.get(), 0, bytes, perVertex.data());
        return success();
    }
    transfer.rest = gl::createBuffer("environment: SH transfer of character " + std::to_string(character));
    glNamedBufferStorage(transfer.rest.get(), bytes, perVertex.data(), GL_DYNAMIC_STORAGE_BIT);
    if (animated) {
        // The rest pose's until the skinning pass turns it (PoseCache re-skins once the transfer exists).
        transfer.posed = gl::createBuffer("environment: posed SH transfer of character " + std::to_string(character));
        glNamedBufferStorage(transfer.posed.get(), bytes, perVertex.data(), 0);
    }
    return success();
}

void GpuEnvironment::attachTransfer(GLuint vertexArray, GLuint buffer) {
    // GpuMesh uses buffer bindings 0 and 1, TsMesh 0 to 3 (render/TsMeshes.cpp).
    constexpr GLuint kTransferBinding = 4;
    glVertexArrayVertexBuffer(vertexArray, kTransferBinding, buffer, 0, sizeof(ShScalar9));
    for (GLuint i = 0; i < 3; ++i) {
        const GLuint location = DERMIS_LOCATION_TRANSFER + i;
        glEnableVertexArrayAttrib(vertexArray, location);
        glVertexArrayAttribFormat(vertexArray, location, 3, GL_FLOAT, GL_FALSE, i * 3 * sizeof(float));
        glVertexArrayAttribBinding(vertexArray, location, kTransferBinding);
    }
}

}  // namespace dermis
