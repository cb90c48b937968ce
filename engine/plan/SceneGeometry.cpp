#include "plan/SceneGeometry.h"

#include "env/ShTransfer.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

// Rays per vertex for findBuriedVertices: a vertex inside the body sees the
// inside of its enclosing part in every direction, one outside in none or
// few, so 16 decide as the reference's crossing parity does (the procedural
// head: 1 of 29,317 vertices disagrees, 717 buried; ShTransfer.FindsTheBuriedVerticesWithSixteenRays
// in tests/unit/test_sh_transfer.cpp).
constexpr int kBuriedVertexRays = 16;

// Whether a layout analysed at one scale serves another: the scale only sets
// the seams' 3 mm probe (mesh/UvLayout.h), and a scale read from a rotated
// transform differs by rounding from frame to frame, which must not analyse
// the layout again.
bool sameScale(float a, float b) { return std::abs(a - b) <= 1e-3f * std::max(std::abs(a), std::abs(b)); }

}  // namespace

SceneGeometry::SceneGeometry(const std::vector<Model>& models) : SceneGeometry(shareModels(models)) {}

SceneGeometry::SceneGeometry(const SceneModels& models) {
    for (const std::shared_ptr<const Model>& shared : models) {
        const Model& model = *shared;
        std::vector<SubmeshMaterial> names;
        for (const Submesh& submesh : model.drawRanges()) {
            const auto index = static_cast<size_t>(submesh.material);
            names.push_back({model.materials[index].name, index, model.materials[index].profile});
        }
        std::vector<float> lodErrors;
        for (const LodLevel& level : model.lods) lodErrors.push_back(level.errorObject);
        mCharacters.push_back({shared, model.mesh.bounds(), nullptr, std::shared_ptr<const Rig>(shared, &model.rig),
                               std::move(names), std::move(lodErrors)});
    }
}

const UvLayout& SceneGeometry::uvLayout(size_t character, float metresPerUnit) {
    Character& c = mCharacters[character];
    if (!c.uvLayout || !sameScale(c.uvLayoutMetresPerUnit, metresPerUnit)) {
        // The old layout stays alive until the new one is made, so the new
        // one never takes its address (TsMeshes keys its meshes by it).
        std::shared_ptr<const UvLayout> layout;
        // Characters that share a model and its scale share its layout.
        for (const Character& other : mCharacters) {
            if (other.model != c.model || !other.uvLayout || !sameScale(other.uvLayoutMetresPerUnit, metresPerUnit)) continue;
            layout = other.uvLayout;
            break;
        }
        if (!layout) {
            UvLayout analysed = analyseUvLayout(c.model->mesh, metresPerUnit);
            // A mesh the tracer refuses (an index out of range) has its
            // error named where it is drawn; here it buries nothing.
            auto buried = findBuriedVertices(c.model->mesh, kBuriedVertexRays);
            if (buried.ok()) analysed.buried = std::move(*buried);
            layout = std::make_shared<const UvLayout>(std::move(analysed));
        }
        c.uvLayout = std::move(layout);
        c.uvLayoutMetresPerUnit = metresPerUnit;
    }
    return *c.uvLayout;
}

Result<std::shared_ptr<const EnvironmentLight>> SceneGeometry::environment(const Environment& environment,
                                                                          size_t sceneLights) const {
    if (!environment.enabled()) return std::shared_ptr<const EnvironmentLight>();
    if (!mEnvironment || mEnvironment->source != environment.source ||
        !(mEnvironment->extraction == lightExtractionSettings(environment, sceneLights))) {
        return makeError(environment.source, "the environment was not loaded before planning (render/SceneLoading.h)");
    }
    return mEnvironment;
}

Bounds transformBounds(const Bounds& b, const glm::mat4& m) {
    Bounds out{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                          (corner & 4) ? b.max.z : b.min.z);
        const glm::vec3 w = glm::vec3(m * glm::vec4(p, 1.0f));
        out.min = glm::min(out.min, w);
        out.max = glm::max(out.max, w);
    }
    return out;
}

}  // namespace dermis
