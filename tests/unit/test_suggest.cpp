// "Did you mean" (core/Suggest.h): the edit distance against worked examples,
// and suggestions only for likely typos.
#include "core/Suggest.h"

#include <gtest/gtest.h>

namespace dermis {
namespace {

TEST(Suggest, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // k->s, e->i, +g (the classic example)
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("taps", "taps"), 0u);
    EXPECT_EQ(editDistance("tpas", "taps"), 1u);  // one swap of neighbours, not two substitutions
    EXPECT_EQ(editDistance("rendr", "render"), 1u);
    EXPECT_EQ(editDistance("ca", "abc"), 3u);  // optimal string alignment: no edit of a swapped pair
}

TEST(Suggest, OnlyLikelyTyposAreSuggested) {
    const std::vector<std::string> commands = {"render", "reference", "stress", "soak", "compare", "bench", "tune", "merge"};
    EXPECT_EQ(closestName("rendr", commands), "render");
    EXPECT_EQ(closestName("refrence", commands), "reference");
    EXPECT_EQ(closestName("tnue", commands), "tune");
    EXPECT_EQ(closestName("bake", commands), "");     // 3 or more edits from every command
    EXPECT_EQ(closestName("xyzzy", commands), "");
    EXPECT_EQ(closestName("render", commands), "");   // the name itself is not a suggestion
    EXPECT_EQ(didYouMean("--frame", {"--frames", "--size"}), " (did you mean '--frames'?)");
    EXPECT_EQ(didYouMean("--colour", {"--frames", "--size"}), "");
}

}  // namespace
}  // namespace dermis
