// Render-graph logic on the test backend: no GL, no GPU.
#include "graph/RenderGraph.h"
#include "graph/TestBackend.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace dermis::graph;

namespace {

const TextureDesc kColour{64, 32, TextureFormat::Rgba16F};

struct One {
    TextureHandle out;
};
struct ReadWrite {
    TextureHandle in;
    TextureHandle out;
};

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

}  // namespace

TEST(RenderGraph, CullsPassWhoseOutputNothingReadsAndNeverRunsIt) {
    RenderGraph graph;
    int producerRuns = 0;
    int orphanRuns = 0;
    int consumerRuns = 0;
    const One& producer = graph.addPass<One>(
        "producer", [](PassBuilder& b, One& d) { d.out = b.create("lit", kColour); },
        [&](const PassResources&, const One&) { ++producerRuns; });
    graph.addPass<One>(
        "orphan", [](PassBuilder& b, One& d) { d.out = b.create("nobody reads this", kColour); },
        [&](const PassResources&, const One&) { ++orphanRuns; });
    const ReadWrite& consumer = graph.addPass<ReadWrite>(
        "consumer",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(producer.out);
            d.out = b.create("final", kColour);
        },
        [&](const PassResources&, const ReadWrite&) { ++consumerRuns; });
    graph.markOutput(consumer.out);

    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);

    EXPECT_EQ(producerRuns, 1);
    EXPECT_EQ(consumerRuns, 1);
    EXPECT_EQ(orphanRuns, 0);
    EXPECT_FALSE(graph.wasExecuted("orphan"));
    EXPECT_FALSE(contains(backend.executedPasses, "orphan"));
    const auto reports = graph.passReports();
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports[1].reason, CullReason::Unused);
    // The orphan's texture was never allocated.
    EXPECT_FALSE(contains(backend.events, "acquire nobody reads this"));
}

TEST(RenderGraph, CullsAWholeUnusedChain) {
    RenderGraph graph;
    int runs = 0;
    const One& a = graph.addPass<One>(
        "a", [](PassBuilder& b, One& d) { d.out = b.create("a", kColour); },
        [&](const PassResources&, const One&) { ++runs; });
    const ReadWrite& b1 = graph.addPass<ReadWrite>(
        "b",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(a.out);
            d.out = b.create("b", kColour);
        },
        [&](const PassResources&, const ReadWrite&) { ++runs; });
    graph.addPass<ReadWrite>(
        "c",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(b1.out);
            d.out = b.create("c", kColour);
        },
        [&](const PassResources&, const ReadWrite&) { ++runs; });
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(runs, 0);
    EXPECT_TRUE(backend.executedPasses.empty());
}

TEST(RenderGraph, SideEffectPassSurvivesWithoutReaders) {
    RenderGraph graph;
    int runs = 0;
    graph.addPass<One>(
        "readback",
        [](PassBuilder& b, One& d) {
            d.out = b.create("scratch", kColour);
            b.sideEffect();
        },
        [&](const PassResources&, const One&) { ++runs; });
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(runs, 1);
}

TEST(RenderGraph, PredicateSkipsPassAndKeepsPreviousContentsOfImportedTexture) {
    // A cached shadow map: the shadow pass is skipped when nothing moved, and
    // the lighting pass reads the imported texture as it was.
    RenderGraph graph;
    const TextureHandle shadow = graph.importTexture("shadow map", {256, 256, TextureFormat::R32F}, 42);
    int shadowRuns = 0;
    BackendTexture seenByLighting = 0;
    const ReadWrite& shadowPass = graph.addPass<ReadWrite>(
        "shadow",
        [&](PassBuilder& b, ReadWrite& d) {
            d.out = b.write(shadow);
            b.skipIf(true, "light and casters unchanged");
        },
        [&](const PassResources&, const ReadWrite&) { ++shadowRuns; });
    const ReadWrite& lighting = graph.addPass<ReadWrite>(
        "lighting",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(shadowPass.out);
            d.out = b.create("lit", kColour);
        },
        [&](const PassResources& r, const ReadWrite& d) { seenByLighting = r.texture(d.in); });
    graph.markOutput(lighting.out);
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(shadowRuns, 0);
    EXPECT_EQ(seenByLighting, 42u);
    const auto reports = graph.passReports();
    EXPECT_EQ(reports[0].reason, CullReason::Predicate);
    EXPECT_EQ(reports[0].detail, "light and casters unchanged");
    EXPECT_TRUE(reports[1].executed);
}

TEST(RenderGraph, PredicateOnCreatorCullsItsReadersButKeepsAliasedWrites) {
    // lighting -> [transmittance adds into irradiance] -> blur. Skipping the
    // transmittance pass leaves the blur reading the lighting result; skipping
    // a pass that creates a texture removes its readers.
    RenderGraph graph;
    const One& lighting = graph.addPass<One>(
        "lighting", [](PassBuilder& b, One& d) { d.out = b.create("irradiance", kColour); },
        [](const PassResources&, const One&) {});
    const ReadWrite& transmit = graph.addPass<ReadWrite>(
        "transmittance",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(lighting.out);
            d.out = b.write(lighting.out);
            b.skipIf(true, "no light behind any SSS surface");
        },
        [](const PassResources&, const ReadWrite&) {});
    const One& ssao = graph.addPass<One>(
        "ssao",
        [](PassBuilder& b, One& d) {
            d.out = b.create("ao", kColour);
            b.skipIf(true, "ssao off");
        },
        [](const PassResources&, const One&) {});
    graph.addPass<ReadWrite>(
        "ssao blur",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(ssao.out);
            d.out = b.create("ao blurred", kColour);
            b.sideEffect();
        },
        [](const PassResources&, const ReadWrite&) {});
    const ReadWrite& blur = graph.addPass<ReadWrite>(
        "blur",
        [&](PassBuilder& b, ReadWrite& d) {
            d.in = b.read(transmit.out);
            d.out = b.create("blurred", kColour);
        },
        [](const PassResources&, const ReadWrite&) {});
    graph.markOutput(blur.out);
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(backend.executedPasses, (std::vector<std::string>{"lighting", "blur"}));
    const auto reports = graph.passReports();
    EXPECT_EQ(reports[3].reason, CullReason::MissingInput);
    EXPECT_EQ(reports[3].detail, "ao");
}

TEST(RenderGraph, TransientTexturesAreRecycledFromThePool) {
    // a -> b -> c -> d: "a" dies after b, so c's texture can reuse it.
    RenderGraph graph;
    TextureHandle previous = graph.addPass<One>(
                                      "p0", [](PassBuilder& b, One& d) { d.out = b.create("t0", kColour); },
                                      [](const PassResources&, const One&) {})
                                 .out;
    for (int i = 1; i < 4; ++i) {
        previous = graph.addPass<ReadWrite>(
                            "p" + std::to_string(i),
                            [&, i](PassBuilder& b, ReadWrite& d) {
                                d.in = b.read(previous);
                                d.out = b.create("t" + std::to_string(i), kColour);
                            },
                            [](const PassResources&, const ReadWrite&) {})
                       .out;
    }
    graph.markOutput(previous);
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(backend.executedPasses.size(), 4u);
    EXPECT_EQ(backend.texturesCreated, 2u);  // ping-pong: two textures serve four
    EXPECT_EQ(backend.liveTextures, 0u);     // everything went back to the pool
}

TEST(RenderGraph, EveryPassIsBracketedByBeginAndEnd) {
    RenderGraph graph;
    const One& a = graph.addPass<One>(
        "a", [](PassBuilder& b, One& d) { d.out = b.create("x", kColour); },
        [](const PassResources&, const One&) {});
    graph.markOutput(a.out);
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    EXPECT_EQ(backend.events, (std::vector<std::string>{"acquire x", "begin a", "end", "release 1"}));
}

TEST(RenderGraph, MisuseIsAnErrorValue) {
    RenderGraph graph;
    graph.addPass<ReadWrite>(
        "bad", [](PassBuilder& b, ReadWrite& d) { d.in = b.read(TextureHandle{}); },
        [](const PassResources&, const ReadWrite&) {});
    const auto status = graph.compile();
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message().find("invalid texture handle"), std::string::npos);
}

// Timings and traces key passes by name: a repeated name is numbered, so
// that two passes never share one row (two SSS slots of one profile did).
TEST(RenderGraph, ARepeatedPassNameIsNumbered) {
    RenderGraph graph;
    for (int i = 0; i < 3; ++i) {
        const One& a = graph.addPass<One>(
            "twin", [](PassBuilder& b, One& d) { d.out = b.create("x", kColour); },
            [](const PassResources&, const One&) {});
        graph.markOutput(a.out);
    }
    ASSERT_TRUE(graph.compile().ok());
    TestBackend backend;
    graph.execute(backend);
    std::vector<std::string> begun;
    for (const std::string& event : backend.events)
        if (event.rfind("begin ", 0) == 0) begun.push_back(event);
    EXPECT_EQ(begun, (std::vector<std::string>{"begin twin", "begin twin#2", "begin twin#3"}));
}

TEST(RenderGraph, WritingAnOldVersionIsAnError) {
    RenderGraph graph;
    const One& a = graph.addPass<One>(
        "a", [](PassBuilder& b, One& d) { d.out = b.create("x", kColour); },
        [](const PassResources&, const One&) {});
    const ReadWrite& b1 = graph.addPass<ReadWrite>(
        "b", [&](PassBuilder& b, ReadWrite& d) { d.out = b.write(a.out); },
        [](const PassResources&, const ReadWrite&) {});
    (void)b1;
    graph.addPass<ReadWrite>(
        "c", [&](PassBuilder& b, ReadWrite& d) { d.out = b.write(a.out); },
        [](const PassResources&, const ReadWrite&) {});
    const auto status = graph.compile();
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message().find("old version"), std::string::npos);
}

TEST(RenderGraph, SkippedChainPassesItsInputThrough) {
    // irradiance -> [blur h -> blur v] x 2 -> composite. The first blur is
    // skipped (too narrow to matter): the second reads the irradiance; with
    // both skipped, composite reads the irradiance directly.
    for (int skipped = 0; skipped <= 2; ++skipped) {
        RenderGraph graph;
        const One& lit = graph.addPass<One>(
            "lighting", [](PassBuilder& b, One& d) { d.out = b.create("irradiance", kColour); },
            [](const PassResources&, const One&) {});
        TextureHandle current = lit.out;
        for (int g = 0; g < 2; ++g) {
            const bool skip = g < skipped;
            const ReadWrite& h = graph.addPass<ReadWrite>(
                "h" + std::to_string(g),
                [&](PassBuilder& b, ReadWrite& d) {
                    d.in = b.read(current);
                    d.out = b.create("tmp" + std::to_string(g), kColour);
                    b.skipIf(skip, "narrower than a pixel");
                },
                [](const PassResources&, const ReadWrite&) {});
            const ReadWrite& v = graph.addPass<ReadWrite>(
                "v" + std::to_string(g),
                [&](PassBuilder& b, ReadWrite& d) {
                    d.in = b.read(h.out);
                    d.out = b.create("blurred" + std::to_string(g), kColour);
                    b.passThrough(d.out, current);
                },
                [](const PassResources&, const ReadWrite&) {});
            current = v.out;
        }
        BackendTexture seen = 0;
        const ReadWrite& composite = graph.addPass<ReadWrite>(
            "composite",
            [&](PassBuilder& b, ReadWrite& d) {
                d.in = b.read(current);
                d.out = b.create("final", kColour);
            },
            [&](const PassResources& r, const ReadWrite& d) { seen = r.texture(d.in); });
        graph.markOutput(composite.out);
        ASSERT_TRUE(graph.compile().ok());
        TestBackend backend;
        graph.execute(backend);
        EXPECT_TRUE(graph.wasExecuted("composite")) << skipped;
        EXPECT_EQ(graph.wasExecuted("h0"), skipped < 1);
        EXPECT_EQ(graph.wasExecuted("v0"), skipped < 1);
        EXPECT_EQ(graph.wasExecuted("h1"), skipped < 2);
        EXPECT_EQ(graph.wasExecuted("v1"), skipped < 2);
        EXPECT_NE(seen, 0u);
        if (skipped == 2) {
            EXPECT_EQ(backend.executedPasses, (std::vector<std::string>{"lighting", "composite"}));
        }
    }
}
