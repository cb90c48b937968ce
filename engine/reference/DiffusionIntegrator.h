#pragma once
// The subsurface integral at a surface point x_o of one character:
//   I(x_o) = integral over the character of R(|x_o - x_i|) E(x_i) albedo^mix(x_i) dA_i
// (docs/reference.md), R the diffusion profile over 3-D distance (1/mm^2),
// dA in mm^2. A midpoint rule over small triangles (cells) whose size follows
// the profile: each Gaussian i of standard deviation s_i sees at least
// `density` samples per s_i^2 within refineCutoffSigmas s_i of x_o, so the
// 80 um Gaussian of skin is resolved near x_o without tessellating the whole
// head at that scale. Base cells (sized for the widest Gaussian) are shaded
// once and shared by every x_o; narrower ones are split per x_o. A cell's
// samples are the centroids of its four children; where two of them disagree
// on a light's visibility (a shadow edge crosses the cell) the children are
// split again, up to `edgeLevels` times, so hard shadows converge like the
// smooth parts. The samples' values come from a SampleValues source (exact
// lighting, or the engine's irradiance texture), passed to each call.

#include "reference/CharacterSurface.h"
#include "reference/SampleValues.h"
#include "reference/SurfaceCells.h"
#include "reference/SurfaceInterior.h"
#include "sss/DiffusionProfile.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::reference {

// Contributions beyond this many of the widest standard deviation are dropped
// (the Gaussian's mass there is exp(-12.5) = 4e-6 of its weight).
constexpr float kQueryCutoffSigmas = 5.0f;
constexpr int kMaxSplitLevels = 14;

struct QuadratureSettings {
    float density = 8.0f;  // samples per s_i^2 (at least) for Gaussian i, near x_o
    // Gaussian i stops asking for finer cells this many s_i from x_o (beyond, its
    // mass exp(-c^2 / 2) of its weight is summed on the coarser cells).
    float refineCutoffSigmas = 4.0f;
    int edgeLevels = 3;  // extra 4-way splits of cells that a shadow edge crosses
};

struct Sample {
    glm::vec3 positionM{0.0f};
    float areaMm2 = 0.0f;
    glm::vec3 value{0.0f};  // E x albedo^mix
};

class DiffusionIntegrator {
public:
    // `surface` must outlive the integrator; the profile is copied. `triangles`
    // (tessellate()) limits the donors to one diffusion group's triangles.
    // Donors inside the body (`interior`, which must outlive the integrator;
    // null: none) give nothing, and a cell that the body's boundary crosses is
    // split like one that a shadow edge crosses.
    DiffusionIntegrator(const CharacterSurface& surface, const DiffusionProfile& profile,
                        const QuadratureSettings& quadrature, const std::vector<uint8_t>* triangles = nullptr,
                        const SurfaceInterior* interior = nullptr);

    // The largest edge of a base cell: (just under) two sample spacings of the widest Gaussian.
    static float baseCellEdgeM(const DiffusionProfile& profile, const QuadratureSettings& quadrature);

    size_t baseCellCount() const { return mBaseCells.size(); }
    float queryRadiusMm() const { return mQueryRadiusMm; }
    // Flags (needed[i] = 1) the base cells that integrate(x_o) may read.
    void markNeeded(const glm::vec3& pointM, std::vector<uint8_t>& needed) const;
    // Shades base cell i with `values` (thread-safe: reads only).
    std::vector<Sample> shadeBaseCell(size_t index, const SampleValues& values) const;
    // I(x_o) from the base cells shaded with the same `values` (baseSamples[i] for
    // every cell markNeeded flagged); finer cells are shaded with `values` too.
    glm::vec3 integrate(const glm::vec3& pointM, const std::vector<std::vector<Sample>>& baseSamples,
                        const SampleValues& values) const;

private:
    struct Shaded {
        Sample sample;
        LightVisibility visibility;
        bool buried = false;
    };
    Shaded shade(const Cell& cell, float childAreaMm2, const SampleValues& values) const;
    // The cell's samples: its four children's centroids, refined at shadow edges.
    template <class Emit>
    void shadeCell(const Cell& cell, float areaMm2, int edgeLevels, const Shaded* knownCentre,
                   const SampleValues& values, Emit&& emit) const;
    // Largest cell edge that Gaussians reaching distance dMinMm need.
    float neededEdgeMm(float dMinMm) const;
    void integrateCell(const Cell& cell, const glm::vec3& pointM, int level, const SampleValues& values,
                       glm::dvec3& sum) const;
    void accumulate(const Sample& s, const glm::vec3& pointM, glm::dvec3& sum) const;
    glm::vec3 profileAt(float radiusSquaredMm2) const;

    const CharacterSurface* mSurface;
    const SurfaceInterior* mInterior;
    QuadratureSettings mQuadrature;
    std::vector<float> mSigmasMm;  // ascending
    struct Term {
        float exponentPerMm2;  // 1 / (2 v)
        glm::vec3 peak;        // w / (2 pi v)
    };
    std::vector<Term> mTerms;
    float mEdgePerSigma;           // sample (child cell) edge / s_i for `density` samples per s_i^2
    float mQueryRadiusMm;
    std::vector<Cell> mBaseCells;
    std::vector<CellShape> mBaseShapes;
    float mMaxBaseBoundMm = 0.0f;
    CellGrid mGrid;
};

}  // namespace dermis::reference
