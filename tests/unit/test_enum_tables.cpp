// The closed sets' tables (core/EnumTable.h): every value has one name that
// round-trips, the scene loader accepts every name and refuses others with the
// list the table generates, and the writer spells values as the table does.
// The ids that reach shaders equal the GLSL constants (checked at compile time).

#include "plan/Aov.h"
#include "gpu/UniformBlocks.h"
#include "scene/JsonReader.h"
#include "scene/SceneEnums.h"
#include "scene/SceneLoader.h"
#include "scene/SssTechniques.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace dermis {
namespace {

static_assert(int(Aov::Normal) == DERMIS_AOV_NORMAL && int(Aov::IrradianceTexture) == DERMIS_AOV_IRRADIANCE_TEXTURE);
static_assert(int(SssBlur::Bilateral) == DERMIS_BLUR_EDGES_BILATERAL && int(SssBlur::Control) == DERMIS_BLUR_EDGES_CONTROL &&
              int(SssBlur::FetchOnly) == DERMIS_BLUR_EDGES_FETCH_ONLY);
static_assert(int(ShadowFilter::Pcf4x4) == DERMIS_SHADOW_FILTER_PCF4X4 && int(ShadowFilter::Poisson) == DERMIS_SHADOW_FILTER_POISSON &&
              int(ShadowFilter::Pcss) == DERMIS_SHADOW_FILTER_PCSS);
static_assert(int(LightType::Spot) == DERMIS_LIGHT_SPOT && int(LightType::Point) == DERMIS_LIGHT_POINT);
static_assert(kMaxBlurTaps == DERMIS_MAX_BLUR_TAPS && kMaxProfileGaussians == DERMIS_MAX_PROFILE_GAUSSIANS);
static_assert(sizeof(gpu::SssBlurBlock::kernel) / sizeof(glm::vec4) == kMaxBlurTaps, "the block holds the longest kernel");

template <typename E, size_t N>
void expectRoundTrips(const EnumTable<E, N>& table) {
    std::set<std::string> names;
    for (const EnumEntry<E>& entry : table) {
        EXPECT_FALSE(entry.name.empty());
        EXPECT_FALSE(entry.description.empty()) << entry.name;
        EXPECT_TRUE(names.insert(std::string(entry.name)).second) << "twice: " << entry.name;
        ASSERT_TRUE(table.parse(entry.name).has_value()) << entry.name;
        EXPECT_EQ(*table.parse(entry.name), entry.value);
        EXPECT_EQ(table.name(entry.value), entry.name);
        EXPECT_NE(table.helpLines("  ").find(std::string(entry.name)), std::string::npos);
    }
    EXPECT_EQ(names.size(), N);
    EXPECT_FALSE(table.parse("").has_value());
    EXPECT_FALSE(table.parse("no such name").has_value());
}

TEST(EnumTables, EveryValueHasOneNameThatRoundTrips) {
    expectRoundTrips(kLightTypes);
    expectRoundTrips(kSssModes);
    expectRoundTrips(kSssVariants);
    expectRoundTrips(kSssBlurs);
    expectRoundTrips(kShadowFilters);
    expectRoundTrips(kAovs);
}

// The technique registry (scene/SssTechniques.cpp) has one descriptor per
// kSssTechniques entry, in its order: a technique added to the enum but not
// to the registry (or the other way round) fails here, in a release build too.
TEST(EnumTables, TheTechniqueRegistryHasOneDescriptorPerTechnique) {
    ASSERT_EQ(sssTechniques().size(), kSssTechniques.size());
    size_t i = 0;
    for (const EnumEntry<SssTechnique>& technique : kSssTechniques) {
        EXPECT_EQ(int(sssTechniques()[i].technique), int(technique.value)) << technique.name;
        EXPECT_FALSE(sssTechniques()[i].candidates.empty()) << technique.name << ": the tuner would never try it";
        const SssLightingScatter& lighting = sssTechniques()[i].lighting;
        if (sssTechniques()[i].scattersInLighting()) {
            EXPECT_TRUE(lighting.glslPrefix && lighting.makeTable && lighting.tableColumns > 0 && lighting.tableRows > 0)
                << technique.name << ": a lighting-pass technique needs its prefix and table";
        }
        ++i;
    }
}

TEST(EnumTables, ListsAndHelpLines) {
    EXPECT_EQ(kSssModes.list(), "ss|ts");
    EXPECT_EQ(kSssVariants.list(", "), "c, lcb, lbb");
    EXPECT_EQ(kSssModes.helpLines("> ", 6), "> ss    screen-space SSS chain (Jimenez et al. 2009)\n"
                                            "> ts    texture-space SSS (d'Eon & Luebke 2007)\n");
    EXPECT_EQ(kAovs.name(static_cast<Aov>(99)), "?");
}

// A scene file with the string `name` at `pointer` and nothing else.
std::string sceneWith(const std::string& pointer, const std::string& name) {
    nlohmann::json document = nlohmann::json::object();
    document[nlohmann::json::json_pointer(pointer)] = name;
    return document.dump();
}

template <typename E, size_t N>
void expectLoaderTakesTheTable(const EnumTable<E, N>& table, const std::string& pointer, E (*read)(const Scene&)) {
    for (const EnumEntry<E>& entry : table) {
        const Result<Scene> scene = parseScene(sceneWith(pointer, std::string(entry.name)), "x.json");
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        EXPECT_EQ(read(*scene), entry.value) << entry.name;
        // The writer spells it as the table does, and it reads back.
        const nlohmann::json written = nlohmann::json::parse(sceneToJson(*scene));
        EXPECT_EQ(written.at(nlohmann::json::json_pointer(pointer)), std::string(entry.name));
    }
    const Result<Scene> bad = parseScene(sceneWith(pointer, "bogus"), "x.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().where, "x.json");
    EXPECT_EQ(bad.error().what, pointer + ": unknown " + std::string(table.noun()) + " \"bogus\" (expected " +
                                    listForMessage(table.names(), "or") + ")");
}

TEST(EnumTables, LoaderAcceptsEveryNameAndRefusesOthersWithTheList) {
    expectLoaderTakesTheTable<SssMode>(kSssModes, "/settings/mode",
                                       [](const Scene& s) { return s.settings.mode; });
    expectLoaderTakesTheTable<SssVariant>(kSssVariants, "/settings/sss/variant",
                                          [](const Scene& s) { return s.settings.sss.variant; });
    expectLoaderTakesTheTable<SssBlur>(kSssBlurs, "/settings/sss/blur",
                                       [](const Scene& s) { return s.settings.sss.blur; });
    expectLoaderTakesTheTable<ShadowFilter>(kShadowFilters, "/settings/shadow/filter",
                                            [](const Scene& s) { return s.settings.shadow.filter; });
    expectLoaderTakesTheTable<LightType>(kLightTypes, "/lights/0/type",
                                         [](const Scene& s) { return s.lights.at(0).type; });
}

TEST(EnumTables, GeneratedMessagesMatchTheFormatManual) {
    // The wording the scene manual and earlier versions used, now generated.
    EXPECT_EQ(listForMessage(kSssModes.names(), "or"), "ss or ts");
    EXPECT_EQ(listForMessage(kSssVariants.names(), "or"), "c, lcb or lbb");
    EXPECT_EQ(listForMessage(kSssBlurs.names(), "or"), "variant, bilateral, control or fetch-only");
    EXPECT_EQ(listForMessage(kShadowFilters.names(), "or"), "pcf4x4, poisson or pcss");
    EXPECT_EQ(listForMessage(kLightTypes.names(), "or"), "directional, spot or point");
}

}  // namespace
}  // namespace dermis
