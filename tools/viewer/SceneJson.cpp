#include "viewer/SceneJson.h"

#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <system_error>

namespace dermis::viewer {
namespace {

using nlohmann::json;

json withoutCamera(const Scene& scene) {
    json document = sceneDocument(scene);
    document.erase("camera");
    return document;
}

std::string dottedKey(const std::string& pointer) {
    std::string key = pointer.substr(pointer.empty() ? 0 : 1);
    for (char& c : key) {
        if (c == '/') c = '.';
    }
    return key;
}

std::string valueAt(const json& document, const std::string& pointer) {
    const json::json_pointer at(pointer);
    return document.contains(at) ? document.at(at).dump() : "";
}

Status readBack(const json& document, Scene& scene) {
    auto parsed = parseScene(document.dump(), scene.path);
    if (!parsed.ok()) return parsed.error();
    parsed->path = scene.path;
    scene = std::move(*parsed);
    return success();
}

}  // namespace

json sceneDocument(const Scene& scene) { return json::parse(sceneToJson(scene)); }

Status setSceneValue(Scene& scene, const std::string& pointer, const json& value) {
    json document = sceneDocument(scene);
    try {
        document[json::json_pointer(pointer)] = value;
    } catch (const json::exception& e) {
        return makeError(pointer, e.what());
    }
    return readBack(document, scene);
}

std::vector<SceneDifference> diffScenes(const Scene& a, const Scene& b) {
    const json documentA = withoutCamera(a);
    const json documentB = withoutCamera(b);
    std::vector<SceneDifference> out;
    for (const json& operation : json::diff(documentA, documentB)) {
        const std::string pointer = operation.at("path").get<std::string>();
        out.push_back({dottedKey(pointer), valueAt(documentA, pointer), valueAt(documentB, pointer)});
    }
    return out;
}

Status mirrorEdit(const Scene& before, const Scene& after, Scene& other) {
    const json patch = json::diff(withoutCamera(before), withoutCamera(after));
    if (patch.empty()) return success();
    json document = sceneDocument(other);
    try {
        document = document.patch(patch);
    } catch (const json::exception& e) {
        return makeError("mirror edit", e.what());
    }
    return readBack(document, other);
}

Status saveSceneJson(const Scene& scene, const std::string& path) {
    if (path.empty()) return makeError("save scene", "no file name given");
    Scene relocated = scene;
    relocated.path = path;  // sceneToJson writes paths relative to scene.path
    const std::string text = sceneToJson(relocated);
    const std::filesystem::path target(path);
    std::error_code error;
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), error);
    const std::filesystem::path temp = target.string() + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary);
        out << text;
        if (!out) return makeError(path, "could not write the file");
    }
    std::filesystem::rename(temp, target, error);
    if (error) {
        std::filesystem::remove(temp, error);
        return makeError(path, "could not write the file");
    }
    return success();
}

}  // namespace dermis::viewer
