#pragma once
// Pass 2: the G-buffer (layout in shaders/gbuffer.frag). The stencil holds
// each pixel's SSS profile slot so later blurs can be confined to skin. In the
// LEAN variants (plan/SssVariant.h) it also holds the view-plane LEAN
// moments (shaders/include/Lean.glsl); in variant c they do not exist.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {

struct GBuffer {
    graph::TextureHandle depthStencil;    // D24S8; stencil = SSS profile slot (0 = opaque)
    graph::TextureHandle albedo;          // RGBA16F linear; alpha = object id / 255
    graph::TextureHandle normalMaterial;  // RGBA16F: octahedral view normal, roughness m, rho_s
    graph::TextureHandle depthKey;        // R32UI: profile slot and view depth (UniformBlocks.glsl)
    graph::TextureHandle scatter;         // RGBA16F: the scattering share s, the volume thickness in mm (docs/materials.md), the curvature in 1/mm
    graph::TextureHandle leanMoments;     // RGBA16F (B'.x, B'.y, M'.xx, M'.yy); invalid in variant c
    graph::TextureHandle leanCross;       // R16F M'.xy; invalid in variant c
    graph::TextureHandle environment;     // RGBA16F: the transfer's L.T and visible share; invalid unless occlusion "transfer"

    bool hasLean() const { return leanMoments.isValid(); }
    // The targets the SSS chain blurs with the irradiance: none in variant c.
    // (leanCross reaches the chain as the irradiance's alpha, LightingPass.h.)
    std::vector<graph::TextureHandle> leanTargets() const {
        return hasLean() ? std::vector<graph::TextureHandle>{leanMoments} : std::vector<graph::TextureHandle>{};
    }
};

GBuffer addGBufferPass(graph::RenderGraph& graph, const FrameContext& frame);

// Declares the reads of a full-screen pass that finds each pixel's surface
// (its stencil test, albedo, normal and material, depth key) and returns
// their handles; the other targets stay invalid.
GBuffer readSurfaceTargets(graph::PassBuilder& builder, const GBuffer& gbuffer);

}  // namespace dermis
