#include "plan/SssPlan.h"

#include "plan/ScreenRegions.h"

#include "plan/ScreenFootprint.h"
#include "plan/SubmeshScattering.h"
#include "gpu/UniformBlocks.h"
#include "scene/SssTechniques.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace dermis {
namespace {

glm::ivec4 unionRect(const glm::ivec4& a, const glm::ivec4& b) {
    if (a.z <= 0 || a.w <= 0) return b;
    if (b.z <= 0 || b.w <= 0) return a;
    const int x0 = std::min(a.x, b.x);
    const int y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.z, b.x + b.z);
    const int y1 = std::max(a.y + a.w, b.y + b.w);
    return glm::ivec4(x0, y0, x1 - x0, y1 - y0);
}

// How many of the profile's Gaussians a choice uses.
int usedGaussians(const DiffusionProfile& profile, const SssChoice& choice) {
    return std::clamp(choice.gaussians, 1, static_cast<int>(profile.gaussians().size()));
}

// A Gaussian's standard deviation in pixels at a scale: what min_width_px is compared with.
float gaussianWidthPx(float varianceMm2, float widthScale, float pixelsPerMm) {
    return std::sqrt(varianceMm2 * (widthScale * widthScale)) * pixelsPerMm;
}

void planSteps(SssSlotPlan& plan, const SssSettings& settings, float pixelsPerMetreAtUnitDepth) {
    const float widthScale2 = plan.widthScale * plan.widthScale;
    const auto& gaussians = plan.profile->gaussians();
    const int used = usedGaussians(*plan.profile, plan.choice);
    std::vector<glm::vec3> weights;
    for (int i = 0; i < used; ++i) weights.push_back(gaussians[static_cast<size_t>(i)].weight);
    for (size_t i = static_cast<size_t>(used); i < gaussians.size(); ++i) weights.back() += gaussians[i].weight;

    const float pixelsPerMm = plan.visible ? pixelsPerMetreAtUnitDepth * 1e-3f / plan.nearestViewDepthM : 0.0f;
    plan.initWeight = glm::vec3(0.0f);
    plan.steps.clear();
    if (sssTechniqueInfo(plan.choice.technique).scattersInLighting()) {
        // The lighting pass scattered already: the chain keeps the whole irradiance.
        for (const glm::vec3& weight : weights) plan.initWeight += weight;
        return;
    }
    float blurredVarianceMm2 = 0.0f;  // of the chain so far: 0 while it is the irradiance itself
    for (int i = 0; i < used; ++i) {
        SssGaussianStep step;
        step.gaussian = i;
        const float variance = gaussians[static_cast<size_t>(i)].varianceMm2 * widthScale2;
        step.weight = weights[static_cast<size_t>(i)];
        step.widthPxAtNearest = gaussianWidthPx(gaussians[static_cast<size_t>(i)].varianceMm2, plan.widthScale, pixelsPerMm);
        step.skipped = !plan.visible || step.widthPxAtNearest < settings.minWidthPx;
        // Only a prefix can be skipped for width (variances increase), so a
        // skipped Gaussian counts as the identity and its weight starts the
        // accumulation.
        if (step.skipped) {
            plan.initWeight += step.weight;
        } else {
            step.readsIrradiance = blurredVarianceMm2 == 0.0f;
            step.stepVarianceMm2 = variance - blurredVarianceMm2;
            blurredVarianceMm2 = variance;
        }
        plan.steps.push_back(step);
    }
}

// The choice for one character's SSS submeshes and its fineness rank among
// this frame's choices: the table row's index, rows.size() for the finest
// (ranks compare only under a budget; without one every choice is the same).
struct RankedChoice {
    SssChoice choice;
    size_t rank = 0;
    const char* source = "settings";
};

// How many of a character's Gaussians (the chain's, from the narrowest) are
// narrower than min_width_px at its own nearest pixel; planSteps skips them
// for a slot at the slot's nearest depth.
int narrowGaussians(const DiffusionProfile& profile, float widthScale, const SssChoice& choice, float pixelsPerMm,
                    float minWidthPx) {
    if (choice.technique != SssTechnique::Gaussians) return 0;
    const auto& gaussians = profile.gaussians();
    const int used = usedGaussians(profile, choice);
    int narrow = 0;
    while (narrow < used &&
           gaussianWidthPx(gaussians[static_cast<size_t>(narrow)].varianceMm2, widthScale, pixelsPerMm) < minWidthPx)
        ++narrow;
    return narrow;
}

RankedChoice chooseFromSettingsOrTable(const Scene& scene, float pixelsPerMm) {
    const QualitySettings& quality = scene.settings.quality;
    if (quality.errorBudget <= 0.0f || quality.loaded.empty()) {
        return {SssChoice::fromSettings(scene.settings.sss), 0, "settings"};
    }
    const size_t row = quality.loaded.rowFor(pixelsPerMm);
    return {quality.loaded.choiceAt(row), row, row < quality.loaded.rows.size() ? "table" : "finest"};
}

// In texture-space mode the lighting pass's irradiance feeds the texture-space
// passes, which must not see a technique's scattering there: a character
// texture space cannot run falls back to the d'Eon chain instead.
RankedChoice chooseSss(const Scene& scene, float pixelsPerMm) {
    RankedChoice ranked = chooseFromSettingsOrTable(scene, pixelsPerMm);
    if (scene.settings.mode == SssMode::TextureSpace && sssTechniqueInfo(ranked.choice.technique).scattersInLighting()) {
        SssChoice chain = ranked.choice;
        chain.technique = SssTechnique::Gaussians;
        ranked.choice = chain.canonical();
    }
    return ranked;
}

Status setChoice(SssSlotPlan& slot, const SssChoice& choice) {
    auto kernel = makeGaussianKernel(choice.taps);
    if (!kernel.ok()) return kernel.error();
    slot.choice = choice;
    slot.gaussianKernel = *kernel;
    return success();
}

}  // namespace

bool SssPlan::anyVisible() const {
    return std::any_of(slots.begin(), slots.end(), [](const SssSlotPlan& s) { return s.visible; });
}

bool scattersInLightingPass(const SssSlotPlan& slot) {
    return slot.visible && sssTechniqueInfo(slot.choice.technique).scattersInLighting();
}

bool blursOnScreen(const SssSlotPlan& slot) {
    if (!slot.visible || scattersInLightingPass(slot)) return false;
    if (slot.choice.technique != SssTechnique::Gaussians) return true;
    return std::any_of(slot.steps.begin(), slot.steps.end(), [](const SssGaussianStep& step) { return !step.skipped; });
}

bool SssPlan::anyScattersInLighting() const { return std::any_of(slots.begin(), slots.end(), scattersInLightingPass); }

bool SssPlan::chainIsIdentity() const {
    const auto wholeIrradiance = [](const SssSlotPlan& s) {
        const glm::vec3 offBy = glm::abs(s.initWeight - glm::vec3(1.0f));
        return std::max({offBy.r, offBy.g, offBy.b}) <= kIdentityInitWeightTolerance;
    };
    return anyVisible() && std::all_of(slots.begin(), slots.end(), [&](const SssSlotPlan& s) {
               return !s.visible || scattersInLightingPass(s) || (!blursOnScreen(s) && wholeIrradiance(s));
           });
}

float ViewParams::pixelsPerMetreAtUnitDepth() const { return 0.5f * float(heightPx) * clipFromView[1][1]; }

bool SssPlan::hasSss(size_t character) const {
    const std::vector<int>& characterSlots = slotsOfCharacter[character];
    return std::any_of(characterSlots.begin(), characterSlots.end(), [](int slot) { return slot > 0; });
}

int SssPlan::slotOf(size_t character, size_t submesh) const {
    if (character >= slotsOfCharacter.size() || submesh >= slotsOfCharacter[character].size()) return 0;
    return slotsOfCharacter[character][submesh];
}

Result<SssPlan> planSss(const Scene& scene, const std::vector<Bounds>& characterBounds, const ViewParams& view,
                        const std::vector<std::vector<SubmeshMaterial>>& submeshMaterials) {
    SssPlan plan;
    plan.slotsOfCharacter.resize(scene.characters.size());
    plan.characterChoices.resize(scene.characters.size());
    std::vector<size_t> slotRanks;
    std::vector<std::vector<glm::ivec4>> characterRects;  // per slot
    const bool budgeted = scene.settings.quality.errorBudget > 0.0f && !scene.settings.quality.loaded.empty();
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const Character& character = scene.characters[c];
        auto submeshes = submeshScattering(scene, c, c < submeshMaterials.size() ? submeshMaterials[c]
                                                                                 : std::vector<SubmeshMaterial>{});
        if (!submeshes.ok()) return submeshes.error();
        ScreenFootprint fp;
        if (scene.settings.sss.enabled && c < characterBounds.size()) fp = screenFootprint(characterBounds[c], view);
        const float pixelsPerMm = fp.visible ? view.pixelsPerMetreAtUnitDepth() * 1e-3f / fp.nearestViewDepthM : 0.0f;
        const RankedChoice ranked = chooseSss(scene, pixelsPerMm);
        CharacterSssChoice& report = plan.characterChoices[c];
        report.pixelsPerMm = pixelsPerMm;
        report.source = ranked.source;
        for (const SubmeshScattering& submesh : *submeshes) {
            if (submesh.profile == nullptr) {
                plan.slotsOfCharacter[c].push_back(0);
                continue;
            }
            auto sameScattering = [&](const SssSlotPlan& s) {
                return s.profile == submesh.profile && s.widthScale == submesh.widthScale;
            };
            // Under a budget the table's rows give characters at different
            // scales slots of their own already.
            const int narrow = budgeted ? 0
                                        : narrowGaussians(*submesh.profile, submesh.widthScale, ranked.choice,
                                                          pixelsPerMm, scene.settings.sss.minWidthPx);
            auto sameChoice = [&](const SssSlotPlan& s) { return sameScattering(s) && s.choice == ranked.choice; };
            auto existing = std::find_if(plan.slots.begin(), plan.slots.end(), [&](const SssSlotPlan& s) {
                return sameChoice(s) && (s.narrowGaussians == narrow || !fp.visible);
            });
            // With every slot taken, one whose characters are at another scale:
            // it skips only what its nearest character may (planSteps).
            if (existing == plan.slots.end() && plan.slots.size() >= DERMIS_MAX_PROFILES) {
                existing = std::find_if(plan.slots.begin(), plan.slots.end(), sameChoice);
            }
            // Under a budget an unseen character may share any slot of its scattering: it covers no pixel.
            if (existing == plan.slots.end() && budgeted && !fp.visible) {
                existing = std::find_if(plan.slots.begin(), plan.slots.end(), sameScattering);
            }
            if (existing == plan.slots.end() && plan.slots.size() >= DERMIS_MAX_PROFILES && budgeted) {
                // Join the nearest finer slot; else make the finest coarser one as fine as this choice.
                std::optional<size_t> finer;
                std::optional<size_t> coarser;
                for (size_t s = 0; s < plan.slots.size(); ++s) {
                    if (!sameScattering(plan.slots[s])) continue;
                    if (slotRanks[s] >= ranked.rank && (!finer || slotRanks[s] < slotRanks[*finer])) finer = s;
                    if (slotRanks[s] < ranked.rank && (!coarser || slotRanks[s] > slotRanks[*coarser])) coarser = s;
                }
                if (!finer && coarser) {
                    if (Status set = setChoice(plan.slots[*coarser], ranked.choice); !set.ok()) return set.error();
                    slotRanks[*coarser] = ranked.rank;
                    finer = coarser;
                }
                if (finer) existing = plan.slots.begin() + static_cast<std::ptrdiff_t>(*finer);
            }
            if (existing == plan.slots.end()) {
                if (plan.slots.size() >= DERMIS_MAX_PROFILES) {
                    return makeError("character '" + character.name + "'",
                                     "more than " + std::to_string(DERMIS_MAX_PROFILES) +
                                         " (diffusion profile, width scale, SSS choice) combinations in one frame");
                }
                SssSlotPlan slot;
                slot.slot = static_cast<int>(plan.slots.size()) + 1;
                slot.profile = submesh.profile;
                slot.widthScale = submesh.widthScale;
                slot.narrowGaussians = narrow;
                const auto sameProfile = std::count_if(plan.slots.begin(), plan.slots.end(), [&](const SssSlotPlan& s) {
                    return s.profile == submesh.profile;
                });
                slot.name = submesh.profile->name() + (sameProfile > 0 ? "#" + std::to_string(sameProfile + 1) : "");
                if (Status set = setChoice(slot, ranked.choice); !set.ok()) return set.error();
                plan.slots.push_back(slot);
                slotRanks.push_back(ranked.rank);
                existing = plan.slots.end() - 1;
            }
            plan.slotsOfCharacter[c].push_back(existing->slot);
            if (!fp.visible) continue;
            existing->nearestViewDepthM =
                existing->visible ? std::min(existing->nearestViewDepthM, fp.nearestViewDepthM) : fp.nearestViewDepthM;
            existing->scissor = existing->visible ? unionRect(existing->scissor, fp.scissor) : fp.scissor;
            existing->visible = true;
            characterRects.resize(plan.slots.size());
            characterRects[static_cast<size_t>(existing->slot - 1)].push_back(fp.scissor);
        }
    }
    for (size_t s = 0; s < characterRects.size(); ++s) plan.slots[s].regions = disjointCover(characterRects[s]);
    for (SssSlotPlan& slot : plan.slots) planSteps(slot, scene.settings.sss, view.pixelsPerMetreAtUnitDepth());
    // Slots may have become finer after a character joined them: report what each renders with.
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        CharacterSssChoice& report = plan.characterChoices[c];
        for (int slot : plan.slotsOfCharacter[c]) {
            if (slot == 0) continue;
            const SssChoice& used = plan.slots[static_cast<size_t>(slot - 1)].choice;
            if (report.pixelsPerMm > 0.0f && budgeted && used != chooseSss(scene, report.pixelsPerMm).choice) {
                report.source = "merged";
            }
            report.hasSss = true;
            report.choice = used;
            break;
        }
    }
    return plan;
}

bool isBackLight(const Light& light, const Bounds& characterBounds, const glm::vec3& cameraPositionM) {
    const glm::vec3 centre = characterBounds.centre();
    const glm::vec3 toLight = light.type == LightType::Directional ? -light.direction : light.positionM - centre;
    const glm::vec3 toCamera = cameraPositionM - centre;
    return glm::dot(toLight, toCamera) < 0.0f;
}

}  // namespace dermis
