#include "render/GpuEnvironment.h"

#include "brdf/EnergyTable.h"
#include "env/PrefilteredEnvironment.h"
#include "env/ShTransferCache.h"
#include "core/Log.h"
#include "gl/TexturePool.h"

#include <cstddef>

namespace dermis {
namespace {

// An RGBA16F lat-long texture of `levels` (level 0 first), u repeating, v clamped, trilinear.
gl::Texture uploadLatLong(const std::vector<Image>& levels, std::string_view label) {
    gl::Texture texture = gl::createTexture2D({static_cast<uint32_t>(levels.front().width),
                                               static_cast<uint32_t>(levels.front().height), graph::TextureFormat::Rgba16F},
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

}  // namespace

static_assert(DERMIS_AVERAGE_ALBEDO_SIZE == kEnergyTableSize, "one average per energy-table row");
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

GpuEnvironment::GpuEnvironment() {
    mUniforms = gl::createBuffer("environment: EnvironmentBlock");
    glNamedBufferStorage(mUniforms.get(), sizeof(gpu::EnvironmentBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    mAverageAlbedo = hemisphericalAverageAlbedo(makeEnergyTable(kEnergyTableSize), kEnergyTableSize);
}

void GpuEnvironment::prepare(const EnvironmentPlan& plan, const Scene& scene) {
    gpu::EnvironmentBlock block{};
    if (plan.enabled()) {
        if (mMapLight != plan.light) {
            const PrefilteredEnvironment prefiltered = PrefilteredEnvironment::build(plan.light->lit());
            mMap = uploadLatLong(prefiltered.levels(), "environment: prefiltered map");
            mMapLevels = static_cast<int>(prefiltered.levels().size());
            mIrradiance = uploadLatLong({plan.light->irradiance}, "environment: irradiance map");
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
    }
    glNamedBufferSubData(mUniforms.get(), 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_ENVIRONMENT, mUniforms.get());
    glBindTextureUnit(DERMIS_UNIT_ENVIRONMENT, mMap.get());
    glBindTextureUnit(DERMIS_UNIT_ENVIRONMENT_IRRADIANCE, mIrradiance.get());
}

Status GpuEnvironment::prepareTransfer(size_t character, const MeshData& mesh, bool animated) {
    if (character < mTransfers.size() && mTransfers[character].rest.isValid()) return success();
    auto loaded = loadOrComputeShTransfer(mesh);
    if (!loaded.ok()) return loaded.error();
    if (mTransfers.size() <= character) mTransfers.resize(character + 1);
    const std::vector<ShScalar9>& perVertex = loaded->transfer.perVertex;
    const auto bytes = static_cast<GLsizeiptr>(perVertex.size() * sizeof(ShScalar9));
    Transfer& transfer = mTransfers[character];
    transfer.rest = gl::createBuffer("environment: SH transfer of character " + std::to_string(character));
    glNamedBufferStorage(transfer.rest.get(), bytes, perVertex.data(), 0);
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
