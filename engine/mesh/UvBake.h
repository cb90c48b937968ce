#pragma once
// Baking maps in a mesh's UV layout: which surface point each texel centre
// maps to (with its tangent frame), and gutter filling beyond the charts.

#include "core/Image.h"
#include "mesh/Mesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace dermis {

struct SurfaceTexel {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 tangent{1.0f, 0.0f, 0.0f};
    glm::vec3 bitangent{0.0f, 1.0f, 0.0f};  // w * cross(normal, tangent): up the image
    float footprintM = 0.0f;                 // the longer side of the surface patch one texel covers
    uint8_t part = 0;                        // the triangle's tag
    bool covered = false;
};

struct SurfaceMap {
    int width = 0;
    int height = 0;
    std::vector<SurfaceTexel> texels;  // row-major, row 0 at v = 0
};

// Rasterises every triangle in UV space at width x height, interpolating its
// corners at each texel centre it covers. trianglePart tags triangles (it may
// be empty: all 0).
SurfaceMap rasteriseSurface(const MeshData& mesh, const std::vector<uint8_t>& trianglePart, int width, int height);

// Calls body(row) for every row, spread over the machine's cores.
void forEachRow(int height, const std::function<void(int row)>& body);

// Grows the covered texels outward by `rings` texels (each new texel the mean
// of its covered neighbours; normalised when `unitVectors`) so that filtering
// at a chart's edge does not pull in what lies beyond it; the rest of the
// image gets `background`.
void fillGutters(Image& image, const SurfaceMap& surface, int rings, const glm::vec4& background, bool unitVectors);

}  // namespace dermis
