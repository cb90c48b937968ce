#pragma once
// Pass 5: the screen-space SSS chain (shaders/include/SssBlur.glsl is the
// method's manual; plan/SssPlan.h decides what runs).
//
//   sss init            accumulation = identity weight x irradiance (SSS pixels), irradiance elsewhere
//   sss <profile> gN h  horizontal step of Gaussian N      \ per profile slot, per Gaussian;
//   sss <profile> gN v  vertical step, += w_N x result      / each skipped by predicate when too narrow
//   sss <profile> disk  the disk technique's slots instead: one pass (passes/SssDiskPass.cpp)
//
// In the LEAN variants the same passes also blur the G-buffer's LEAN moments
// (addSssChain); in variant c they are neither declared nor blurred.
//
// Every blur runs under the stencil test (its slot) and the slot's scissor.
// With no SSS pixel on screen every pass is skipped and readers of the
// result get the irradiance itself (passThrough).

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"
#include "plan/SssVariant.h"

#include <vector>

namespace dermis {

struct SssChain {
    graph::TextureHandle diffuse;               // accumulated irradiance
    std::vector<graph::TextureHandle> extras;   // accumulated extra targets, in the order given
};

// Screen-space SSS: `sss init`, then each technique's passes for the slots
// whose choice (plan/SssPlan.h, SssChoice) is that technique, as the
// technique registry lists them (passes/SssTechniquePasses.cpp). The returned targets hold the scattered
// irradiance (and extras) on the SSS pixels and the inputs' values
// everywhere else; with SSS disabled or no SSS pixel on screen every pass is
// culled and readers get the inputs themselves.
SssChain addSssChain(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                     graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras,
                     graph::TextureHandle hiddenSide);

// What `sss init` starts: the accumulations (colour, extras) and the chain
// the first blur reads (the irradiance itself, or the packed chain).
struct SssStart {
    SssChain accumulated;
    graph::TextureHandle chain;
    graph::TextureHandle hiddenSide;  // passes/ThinEdgePasses.h: read by every technique at DERMIS_UNIT_HIDDEN_SIDE
    graph::TextureDesc chainDesc;
    bool packed = false;
};
// The `sss init` pass: SSS pixels start their accumulation at the profile's
// identity weight x the irradiance (a technique that overwrites every SSS
// pixel of its slot may ignore that), every other pixel keeps its input.
SssStart addSssInit(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                    graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras);

// Each technique's passes for the slots whose choice is that technique
// (others are left alone), reading the chain start and adding into `chain`,
// which it returns: a technique's last pass either adds w x its result into
// the accumulations by blending (after sss init's identity weight, as the
// d'Eon chain does) or overwrites every pixel of its slot.
//
// A technique's passes: they read the chain start and add into `chain`, which they return.
using AddSssTechniquePasses = SssChain (*)(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                           const SssStart& start, SssChain chain);
// The GL half of the technique registry (scene/SssTechniques.h): a
// technique's passes; null for one that adds none (it scatters in the
// lighting pass: SssTechniqueInfo::scattersInLighting).
AddSssTechniquePasses sssTechniquePasses(SssTechnique technique);

constexpr int kAnySssPixel = -1;

// Every technique's edge handling for one slot (include/SssEdges.glsl).
gpu::SssEdgeParams sssEdgeParams(const SssSettings& settings, int slot);

// The union of the visible slots' scissors (whole frame if none).
glm::ivec4 sssScissor(const SssPlan& plan);

// Scissor plus a read-only stencil test for the duration of a draw:
// stencil == slot, or != 0 for kAnySssPixel. Depth test and writes off.
class ScopedSssState {
public:
    ScopedSssState(const FrameContext& frame, const glm::ivec4& scissor, int slot);
    ~ScopedSssState();
    ScopedSssState(const ScopedSssState&) = delete;
    ScopedSssState& operator=(const ScopedSssState&) = delete;
};

}  // namespace dermis
