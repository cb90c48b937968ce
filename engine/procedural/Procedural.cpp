#include "procedural/Procedural.h"

#include "procedural/HeadMapsCache.h"
#include "procedural/ProceduralHead.h"
#include "procedural/ProceduralRig.h"
#include "procedural/ProceduralShapes.h"

#include <memory>
#include <mutex>

namespace dermis {
namespace {

constexpr int kHeadAlbedoSize = 1024;
constexpr int kHeadNormalSize = 2048;

Model makeHeadModel() {
    HeadMesh head = makeHeadMesh();
    HeadMaps maps = loadOrBakeHeadMaps(head, kHeadAlbedoSize, kHeadNormalSize);
    Model model;
    model.materials[0].albedoMap = std::move(maps.albedo);
    model.materials[0].normalMap = std::move(maps.normal);
    model.mesh = std::move(head.mesh);
    return model;
}

Model modelOf(MeshData mesh) {
    Model model;
    model.mesh = std::move(mesh);
    return model;
}

}  // namespace

std::vector<std::string> proceduralModelNames() { return {"head", "nodding_head", "plane", "sphere", "wedge"}; }

Result<Model> makeProceduralModel(const std::string& name) {
    if (name == "head" || name == "nodding_head") {
        // Seconds to generate (without the maps cache) and deterministic: made once per
        // process, copied after.
        static std::mutex sMutex;
        static std::unique_ptr<Model> sHead;
        std::unique_lock<std::mutex> lock(sMutex);
        if (!sHead) sHead = std::make_unique<Model>(makeHeadModel());
        Model model = *sHead;
        lock.unlock();
        if (name == "nodding_head") addNoddingRig(model);
        return model;
    }
    if (name == "plane") return modelOf(makePlaneMesh());
    if (name == "sphere") return modelOf(makeSphereMesh());
    if (name == "wedge") return modelOf(makeWedgeMesh());

    std::string known;
    for (const std::string& candidate : proceduralModelNames()) known += (known.empty() ? "" : ", ") + candidate;
    return makeError("", "unknown procedural mesh \"" + name + "\" (known: " + known + ")");
}

}  // namespace dermis
