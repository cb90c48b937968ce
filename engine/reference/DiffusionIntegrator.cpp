#include "reference/DiffusionIntegrator.h"

#include <algorithm>
#include <cmath>

namespace dermis::reference {
namespace {

constexpr float kMmPerM = 1000.0f;
constexpr float kMm2PerM2 = 1e6f;
constexpr float kPi = 3.14159265358979f;
// exp(-40) = 4e-18: a Gaussian this far below its peak adds nothing a float sum keeps.
constexpr float kNegligibleExponent = 40.0f;

// An equilateral sample cell of edge h has area (sqrt 3 / 4) h^2 = s^2 / density.
float edgePerSigma(float density) { return std::sqrt(4.0f / (std::sqrt(3.0f) * std::max(density, 1e-6f))); }

}  // namespace

DiffusionIntegrator::DiffusionIntegrator(const CharacterSurface& surface, const DiffusionProfile& profile,
                                         const QuadratureSettings& quadrature, const std::vector<uint8_t>* triangles,
                                         const SurfaceInterior* interior)
    : mSurface(&surface), mInterior(interior), mQuadrature(quadrature) {
    for (const ProfileGaussian& g : profile.gaussians()) {
        mSigmasMm.push_back(std::sqrt(g.varianceMm2));
        mTerms.push_back(Term{0.5f / g.varianceMm2, g.weight / (2.0f * kPi * g.varianceMm2)});
    }
    mEdgePerSigma = edgePerSigma(quadrature.density);
    mQueryRadiusMm = kQueryCutoffSigmas * mSigmasMm.back();

    mBaseCells = tessellate(surface, baseCellEdgeM(profile, quadrature), triangles);
    std::vector<glm::vec3> centroids;
    centroids.reserve(mBaseCells.size());
    mBaseShapes.reserve(mBaseCells.size());
    for (const Cell& cell : mBaseCells) {
        const CellShape shape = cellShape(surface, cell);
        mBaseShapes.push_back(shape);
        centroids.push_back(shape.centroidM);
        mMaxBaseBoundMm = std::max(mMaxBaseBoundMm, shape.boundRadiusM * kMmPerM);
    }
    mGrid = CellGrid(centroids, (mQueryRadiusMm + mMaxBaseBoundMm) / kMmPerM);
}

float DiffusionIntegrator::baseCellEdgeM(const DiffusionProfile& profile, const QuadratureSettings& quadrature) {
    // Acceptable as they are for the widest Gaussian, whose samples (the children) may be edgePerSigma s_max
    // apart; the 0.999 keeps every base cell within that test despite rounding.
    return 0.999f * 2.0f * edgePerSigma(quadrature.density) * std::sqrt(profile.gaussians().back().varianceMm2) / kMmPerM;
}

float DiffusionIntegrator::neededEdgeMm(float dMinMm) const {
    for (float sigmaMm : mSigmasMm) {
        if (dMinMm < mQuadrature.refineCutoffSigmas * sigmaMm) return 2.0f * mEdgePerSigma * sigmaMm;
    }
    return 2.0f * mEdgePerSigma * mSigmasMm.back();
}

void DiffusionIntegrator::markNeeded(const glm::vec3& pointM, std::vector<uint8_t>& needed) const {
    mGrid.forEachNear(pointM, (mQueryRadiusMm + mMaxBaseBoundMm) / kMmPerM, [&](uint32_t index) { needed[index] = 1; });
}

DiffusionIntegrator::Shaded DiffusionIntegrator::shade(const Cell& cell, float childAreaMm2,
                                                       const SampleValues& values) const {
    const glm::vec2 b = cellCentroid(cell);
    Shaded shaded;
    shaded.sample.positionM = mSurface->positionAt(cell.triangle, b.x, b.y);
    shaded.sample.areaMm2 = childAreaMm2;
    shaded.buried = mInterior && mInterior->buried(cell.triangle, b.x, b.y);
    // Surface inside the body is no boundary: no light enters there (SurfaceInterior.h).
    if (!shaded.buried) shaded.sample.value = values.valueAt(cell.triangle, b, &shaded.visibility);
    return shaded;
}

template <class Emit>
void DiffusionIntegrator::shadeCell(const Cell& cell, float areaMm2, int edgeLevels, const Shaded* knownCentre,
                                    const SampleValues& values, Emit&& emit) const {
    const std::array<Cell, 4> children = splitCell(cell);
    const float childAreaMm2 = 0.25f * areaMm2;
    std::array<Shaded, 4> shaded;
    for (size_t c = 0; c < 4; ++c) {
        // The middle child's centroid is the parent's: reuse it when the parent was shaded.
        if (c == 3 && knownCentre) {
            shaded[c] = *knownCentre;
            shaded[c].sample.areaMm2 = childAreaMm2;
        } else {
            shaded[c] = shade(children[c], childAreaMm2, values);
        }
    }
    bool edge = false;
    for (size_t i = 0; i < 4 && !edge; ++i) {
        for (size_t j = i + 1; j < 4; ++j)
            edge = edge || shaded[i].visibility.disagreesWith(shaded[j].visibility) || shaded[i].buried != shaded[j].buried;
    }
    if (edge && edgeLevels > 0) {
        for (size_t c = 0; c < 4; ++c) shadeCell(children[c], childAreaMm2, edgeLevels - 1, &shaded[c], values, emit);
        return;
    }
    for (const Shaded& s : shaded) emit(s.sample);
}

std::vector<Sample> DiffusionIntegrator::shadeBaseCell(size_t index, const SampleValues& values) const {
    std::vector<Sample> samples;
    shadeCell(mBaseCells[index], mBaseShapes[index].areaM2 * kMm2PerM2, mQuadrature.edgeLevels, nullptr, values,
              [&](const Sample& s) { samples.push_back(s); });
    return samples;
}

// DiffusionProfile::radialProfile's sum (Chappuis 2011 §2.1.4), in float, for the inner loop.
glm::vec3 DiffusionIntegrator::profileAt(float radiusSquaredMm2) const {
    glm::vec3 sum(0.0f);
    for (const Term& term : mTerms) {
        const float exponent = term.exponentPerMm2 * radiusSquaredMm2;
        if (exponent < kNegligibleExponent) sum += term.peak * std::exp(-exponent);
    }
    return sum;
}

void DiffusionIntegrator::accumulate(const Sample& s, const glm::vec3& pointM, glm::dvec3& sum) const {
    const glm::vec3 dMm = (s.positionM - pointM) * kMmPerM;
    sum += glm::dvec3(profileAt(glm::dot(dMm, dMm)) * (s.value * s.areaMm2));
}

void DiffusionIntegrator::integrateCell(const Cell& cell, const glm::vec3& pointM, int level,
                                        const SampleValues& values, glm::dvec3& sum) const {
    const CellShape shape = cellShape(*mSurface, cell);
    const float dMinMm = std::max(0.0f, glm::length(shape.centroidM - pointM) - shape.boundRadiusM) * kMmPerM;
    if (dMinMm > mQueryRadiusMm) return;
    if (shape.maxEdgeM * kMmPerM > neededEdgeMm(dMinMm) && level < kMaxSplitLevels) {
        for (const Cell& child : splitCell(cell)) integrateCell(child, pointM, level + 1, values, sum);
        return;
    }
    shadeCell(cell, shape.areaM2 * kMm2PerM2, mQuadrature.edgeLevels, nullptr, values,
              [&](const Sample& s) { accumulate(s, pointM, sum); });
}

glm::vec3 DiffusionIntegrator::integrate(const glm::vec3& pointM, const std::vector<std::vector<Sample>>& baseSamples,
                                         const SampleValues& values) const {
    glm::dvec3 sum(0.0);
    mGrid.forEachNear(pointM, (mQueryRadiusMm + mMaxBaseBoundMm) / kMmPerM, [&](uint32_t index) {
        const CellShape& shape = mBaseShapes[index];
        const float dMinMm = std::max(0.0f, glm::length(shape.centroidM - pointM) - shape.boundRadiusM) * kMmPerM;
        if (dMinMm > mQueryRadiusMm) return;
        if (shape.maxEdgeM * kMmPerM <= neededEdgeMm(dMinMm)) {
            for (const Sample& s : baseSamples[index]) accumulate(s, pointM, sum);
        } else {
            for (const Cell& child : splitCell(mBaseCells[index])) integrateCell(child, pointM, 1, values, sum);
        }
    });
    return glm::vec3(sum);
}

}  // namespace dermis::reference
