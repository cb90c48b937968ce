// --shard K/N (tools/shards/ShardSpec.h): the parts cover every item once, in
// order, with sizes that differ by at most one; bad specs name the option.
#include "shards/ShardSpec.h"

#include <gtest/gtest.h>

#include <vector>

namespace dermis::shards {
namespace {

TEST(ShardSpec, PartsCoverEveryItemOnceInOrder) {
    for (int count : {1, 2, 3, 7, 64}) {
        for (int items : {0, 1, 5, 36, 180, 1001}) {
            int next = 0, smallest = items, largest = 0;
            for (int k = 1; k <= count; ++k) {
                const ShardRange range = shardRange({k, count}, items);
                EXPECT_EQ(range.first, next) << k << "/" << count << " of " << items;
                next += range.count;
                smallest = std::min(smallest, range.count);
                largest = std::max(largest, range.count);
            }
            EXPECT_EQ(next, items) << count << " shards of " << items;
            EXPECT_LE(largest - smallest, 1) << count << " shards of " << items;
        }
    }
}

TEST(ShardSpec, StridesTakeEveryItemOnceAndMixTheOrder) {
    for (int count : {1, 2, 3, 7, 64}) {
        for (int items : {0, 1, 5, 36, 180, 1001}) {
            std::vector<int> takenBy(size_t(items), 0);
            int smallest = items, largest = 0;
            for (int k = 1; k <= count; ++k) {
                const ShardStride stride = shardStride({k, count}, items);
                for (int i = 0; i < stride.count; ++i) {
                    ASSERT_LT(stride.item(i), items) << k << "/" << count << " of " << items;
                    ++takenBy[size_t(stride.item(i))];
                    // Consecutive items go to different shards: each shard gets a like mix of the order.
                    if (i > 0) EXPECT_EQ(stride.item(i) - stride.item(i - 1), count);
                }
                smallest = std::min(smallest, stride.count);
                largest = std::max(largest, stride.count);
            }
            for (int item = 0; item < items; ++item) EXPECT_EQ(takenBy[size_t(item)], 1) << item << " of " << items;
            EXPECT_LE(largest - smallest, 1) << count << " shards of " << items;
        }
    }
}

TEST(ShardSpec, ParsesKOverN) {
    auto spec = parseShardSpec("2/5");
    ASSERT_TRUE(spec.ok());
    EXPECT_EQ(spec->index, 2);
    EXPECT_EQ(spec->count, 5);
    for (const char* bad : {"", "2", "/5", "2/", "6/5", "0/5", "-1/5", "1/0", "a/b", "1/5000", "1.5/2"}) {
        auto refused = parseShardSpec(bad);
        ASSERT_FALSE(refused.ok()) << bad;
        EXPECT_EQ(refused.error().where, std::string("--shard ") + bad);
    }
}

}  // namespace
}  // namespace dermis::shards
