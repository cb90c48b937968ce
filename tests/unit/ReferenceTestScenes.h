#pragma once
// Small in-memory scenes for the CPU reference's tests (no files, no GL).

#include "reference/ReferenceRenderer.h"
#include "procedural/Procedural.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>

namespace dermis::test {

// A character using the given procedural mesh, without maps.
inline Character proceduralCharacter(const std::string& name, const std::string& mesh, const std::string& profile) {
    Character character;
    character.name = name;
    character.mesh.procedural = mesh;
    character.material.albedo = glm::vec3(1.0f);
    character.material.profile = profile;
    return character;
}

inline Model proceduralModelWithoutMaps(const std::string& name) {
    Model model = std::move(makeProceduralModel(name).value());
    model.materials[0].albedoMap = Image{};
    model.materials[0].normalMap = Image{};
    return model;
}

// A quad (two triangles, counter-clockwise seen from +normal) in world metres.
inline Model quadModel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
    Model model;
    const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    for (const glm::vec3& p : {a, b, c, d}) {
        Vertex v;
        v.position = p;
        v.normal = normal;
        model.mesh.vertices.push_back(v);
    }
    model.mesh.indices = {0, 1, 2, 0, 2, 3};
    return model;
}

// Lighting that isolates the integral: no ambient, no energy conservation, mix 1
// (the albedo acts before the scattering only).
inline Scene bareScene() {
    Scene scene;
    scene.settings.ambient = glm::vec3(0.0f);
    scene.settings.energyConservation = false;
    scene.settings.sss.mix = 1.0f;
    return scene;
}

inline Light sunFromAbove(float intensity = 1.0f) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.intensity = intensity;
    light.castsShadow = true;
    return light;
}

// A ray straight down onto the y = 0 plane at (xM, zM), starting just above it.
inline raytrace::Ray downAt(float xM, float zM) {
    return raytrace::Ray{glm::vec3(xM, 0.01f, zM), glm::vec3(0.0f, -1.0f, 0.0f)};
}

}  // namespace dermis::test

namespace dermis::test {

// The procedural sphere (radius 0.1 m at the origin) under a spot light from the
// upper left, a small opaque card between them casting a hard shadow on it, seen
// from +Z. With `maps`, a checker albedo map (sRGB) and a tilted-normal map.
inline Scene sphereScene() {
    Scene scene;
    scene.camera.positionM = glm::vec3(0.0f, 0.0f, 0.45f);
    scene.camera.targetM = glm::vec3(0.0f);
    scene.camera.verticalFovDeg = 30.0f;
    Light spot;
    spot.type = LightType::Spot;
    spot.positionM = glm::vec3(-0.5f, 0.3f, 0.4f);
    spot.direction = glm::normalize(-spot.positionM);
    spot.intensity = 0.8f;
    spot.spotInnerDeg = 15.0f;
    spot.spotOuterDeg = 25.0f;
    scene.lights.push_back(spot);
    scene.settings.ambient = glm::vec3(0.02f);
    scene.characters.push_back(proceduralCharacter("sphere", "sphere", "skin"));
    scene.characters[0].material.albedo = glm::vec3(0.9f, 0.7f, 0.6f);
    scene.characters.push_back(proceduralCharacter("card", "", "none"));
    return scene;
}

inline std::vector<Model> sphereSceneModels(bool maps) {
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("sphere"));
    if (maps) {
        Image albedo;
        albedo.width = albedo.height = 4;
        albedo.colourSpace = ColourSpace::Srgb;
        Image normal = albedo;
        normal.colourSpace = ColourSpace::Linear;
        for (int i = 0; i < 16; ++i) {
            albedo.texels.push_back((i + i / 4) % 2 ? glm::vec4(0.9f, 0.8f, 0.7f, 1.0f) : glm::vec4(0.6f, 0.5f, 0.5f, 1.0f));
            normal.texels.push_back(i % 3 ? glm::vec4(0.5f, 0.5f, 1.0f, 1.0f) : glm::vec4(0.7f, 0.4f, 0.9f, 1.0f));
        }
        models[0].materials[0].albedoMap = albedo;
        models[0].materials[0].normalMap = normal;
    }
    // The card: 4 cm square, a third of the way from the light to the sphere.
    const glm::vec3 centre = glm::vec3(-0.5f, 0.3f, 0.4f) * 0.6f;
    const glm::vec3 axis = glm::normalize(centre);
    const glm::vec3 u = glm::normalize(glm::cross(axis, glm::vec3(0.0f, 1.0f, 0.0f))) * 0.02f;
    const glm::vec3 v = glm::normalize(glm::cross(u, axis)) * 0.02f;
    models.push_back(quadModel(centre - u - v, centre + u - v, centre + u + v, centre - u + v));
    return models;
}

}  // namespace dermis::test
