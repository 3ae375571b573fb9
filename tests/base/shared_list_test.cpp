// SharedList: copies share their items until written, and otherwise behave as a vector.
#include "core/base/shared_list.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

namespace inkray {
namespace {

SharedList<std::string> numbered(int n) {
  SharedList<std::string> list;
  for (int i = 0; i < n; ++i) list.push_back(std::to_string(i));
  return list;
}

size_t shared_items(const SharedList<std::string>& a, const SharedList<std::string>& b) {
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += a.shares(b, i);
  return n;
}

TEST(SharedList, ACopySharesEveryItem) {
  const SharedList<std::string> a = numbered(300);
  const SharedList<std::string> b =
      a;  // NOLINT(performance-unnecessary-copy-initialization): the copy is the test
  EXPECT_EQ(shared_items(a, b), 300u);
  EXPECT_EQ(a, b);
}

TEST(SharedList, AWriteCopiesOneItemAndLeavesTheOriginal) {
  const SharedList<std::string> a = numbered(300);
  SharedList<std::string> b = a;
  b[130] = "changed";
  EXPECT_EQ(a[130], "130");
  EXPECT_EQ(b[130], "changed");
  EXPECT_EQ(shared_items(a, b), 299u);
  EXPECT_FALSE(a == b);
  b[130] = "130";
  EXPECT_EQ(a, b);  // equal by value though no longer shared
}

TEST(SharedList, WritesThroughIteratorsBackAndAtAreTheCopysOwn) {
  const SharedList<std::string> a = numbered(70);
  SharedList<std::string> b = a;
  *(b.begin() + 3) = "x";
  b.back() = "y";
  b.at(65) = "z";
  EXPECT_EQ(a[3], "3");
  EXPECT_EQ(a[69], "69");
  EXPECT_EQ(a[65], "65");
  EXPECT_EQ(shared_items(a, b), 67u);
  EXPECT_THROW((void)b.at(70), std::out_of_range);
}

TEST(SharedList, InsertAndEraseKeepTheOrderAndTheSharing) {
  const SharedList<std::string> a = numbered(200);
  SharedList<std::string> b = a;
  const SharedList<std::string>& read = b;  // a non-const operator[] would take the item for writing
  b.insert(b.begin() + 10, "new");
  ASSERT_EQ(b.size(), 201u);
  EXPECT_EQ(read[9], "9");
  EXPECT_EQ(read[10], "new");
  EXPECT_EQ(read[11], "10");
  EXPECT_EQ(read[200], "199");
  b.erase(b.begin() + 10);
  EXPECT_EQ(b, a);
  EXPECT_EQ(shared_items(a, b), 200u);  // no item was copied, only the chunks
  b.erase(b.begin(), b.begin() + 150);
  ASSERT_EQ(b.size(), 50u);
  EXPECT_EQ(read.front(), "150");
  EXPECT_EQ(a.size(), 200u);
}

TEST(SharedList, EraseIfRemovesWhatThePredicateSays) {
  SharedList<std::string> list = numbered(130);
  EXPECT_EQ(list.erase_if([](const std::string& s) { return s.back() == '7'; }), 13u);
  EXPECT_EQ(list.size(), 117u);
  EXPECT_TRUE(std::none_of(list.begin(), list.end(), [](const std::string& s) { return s.back() == '7'; }));
  EXPECT_EQ(list.erase_if([](const std::string&) { return false; }), 0u);
}

TEST(SharedList, UpdateIfTakesOnlyTheItemsItChanges) {
  const SharedList<std::string> a = numbered(300);
  SharedList<std::string> b = a;
  EXPECT_EQ(b.update_if([](const std::string& s) { return s.size() == 1; }, [](std::string& s) { s += "!"; }),
            10u);
  EXPECT_EQ(shared_items(a, b), 290u);
  EXPECT_EQ(std::as_const(b)[7], "7!");
  EXPECT_EQ(a[7], "7");
}

TEST(SharedList, WorksWithTheStandardAlgorithms) {
  SharedList<int> list{5, 3, 9, 1, 7};
  std::sort(list.begin(), list.end());
  EXPECT_EQ(list.to_vector(), (std::vector<int>{1, 3, 5, 7, 9}));
  EXPECT_EQ(std::accumulate(list.begin(), list.end(), 0), 25);
  const SharedList<int>& read = list;
  EXPECT_EQ(std::find(read.begin(), read.end(), 7) - read.begin(), 3);
  EXPECT_EQ(read.end() - read.begin(), 5);
  list.resize(7);
  EXPECT_EQ(list[6], 0);
  list.pop_back();
  list.clear();
  EXPECT_TRUE(list.empty());
}

TEST(SharedList, PopAndShrinkLeaveTheOriginalAndTheRestShared) {
  const SharedList<std::string> a = numbered(130);
  SharedList<std::string> b = a;
  b.pop_back();
  b.pop_back();  // the last chunk held two items: it goes
  ASSERT_EQ(b.size(), 128u);
  EXPECT_EQ(std::as_const(b).back(), "127");
  EXPECT_EQ(shared_items(a, b), 128u);
  b.resize(70);
  EXPECT_EQ(b.size(), 70u);
  EXPECT_EQ(shared_items(a, b), 70u);
  b.push_back("new");
  EXPECT_EQ(std::as_const(b)[70], "new");
  EXPECT_EQ(a.size(), 130u);
  EXPECT_EQ(a[70], "70");
}

TEST(SharedList, AppendingToACopyLeavesTheOriginal) {
  const SharedList<std::string> a = numbered(64);  // a full chunk
  SharedList<std::string> b = a;
  b.push_back("64");
  SharedList<std::string> c = numbered(63);
  SharedList<std::string> d = c;
  d.emplace_back("last");  // into the shared, partly full chunk
  EXPECT_EQ(a.size(), 64u);
  EXPECT_EQ(c.size(), 63u);
  EXPECT_EQ(d.back(), "last");
  EXPECT_EQ(shared_items(c, d), 63u);
}

}  // namespace
}  // namespace inkray
