// Node ids (core/machine/node_id.h) are their own type: a node id where a vertex index is wanted,
// or the other way round, does not compile. The machine's loops are indexed by NodeId alone.
#include <gtest/gtest.h>

#include <type_traits>

#include "machine/loops.h"
#include "machine/node_id.h"

using namespace flood;

static_assert(!std::is_convertible_v<NodeId, Index>, "a node id is not a vertex index");
static_assert(!std::is_convertible_v<Index, NodeId>, "a vertex index is not a node id");
static_assert(!std::is_convertible_v<NodeId, size_t>, "nodes are indexed by NodeId alone");
static_assert(std::is_same_v<decltype(Node{}.v), Index> &&
                  std::is_same_v<decltype(Node{}.next), NodeId>,
              "a node refers to its vertex by Index and to its neighbours by NodeId");

TEST(NodeId, OffsetsCountFromAPartsFirstNode) {
    const NodeId first{7};
    EXPECT_EQ((first + 5) - first, 5u);
    EXPECT_LT(first, first + 1);
    Nodes nodes;
    EXPECT_EQ(nodes.end(), NodeId(0));
    nodes.push(Node{3, NodeId(0), NodeId(0)});
    EXPECT_EQ(nodes.end(), NodeId(1));
    EXPECT_EQ(nodes[NodeId(0)].v, 3u);
}
