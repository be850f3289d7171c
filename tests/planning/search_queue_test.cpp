#include <gtest/gtest.h>

#include "ringlet/planning/search_queue.hpp"

namespace ringlet::planning {
namespace {

TEST(SearchQueue, PopsInKeyOrderWithTiesToTheLowerVertex) {
  SearchQueue q;
  q.reserve(10);
  q.push_or_update(7, {20, 10});
  q.push_or_update(3, {10, 50});
  q.push_or_update(5, {10, 20});
  q.push_or_update(1, {20, 10});
  q.push_or_update(9, {5, 90});
  std::vector<int> order;
  while (!q.empty()) order.push_back(q.pop());
  EXPECT_EQ(order, (std::vector<int>{9, 5, 3, 1, 7}));
}

TEST(SearchQueue, UpdateMovesBothWaysAndRemoveKeepsTheHeap) {
  SearchQueue q;
  q.reserve(8);
  for (int v = 0; v < 8; ++v) q.push_or_update(v, {v, 0});
  q.push_or_update(6, {-1, 0});  // decrease
  q.push_or_update(0, {10, 0});  // increase
  q.remove(3);
  q.remove(3);  // twice: no effect
  EXPECT_FALSE(q.contains(3));
  EXPECT_TRUE(q.contains(6));
  EXPECT_EQ(q.top_key(), (SearchKey{-1, 0}));
  std::vector<int> order;
  while (!q.empty()) order.push_back(q.pop());
  EXPECT_EQ(order, (std::vector<int>{6, 1, 2, 4, 5, 7, 0}));
  q.push_or_update(2, {1, 1});
  q.clear();
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.contains(2));
}

}  // namespace
}  // namespace ringlet::planning
