#include "ncbridge/bus/rendezvous.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

using namespace ncbridge::bus;

namespace {

std::vector<std::string> workers(int n) {
  std::vector<std::string> w;
  for (int i = 0; i < n; ++i) w.push_back("host-" + std::to_string(i % 3) + "/" + std::to_string(4000 + 17 * i));
  return w;
}

std::vector<std::string> job_ids(int n) {
  std::vector<std::string> ids;
  for (int i = 0; i < n; ++i) ids.push_back("job-" + std::to_string(i));
  return ids;
}

std::string owner_of(const std::string& job, const std::vector<std::string>& ws) {
  return ws[*rendezvous_owner(job, ws)];
}

}  // namespace

TEST(Rendezvous, NoWorkersNoOwner) {
  EXPECT_FALSE(rendezvous_owner("job", {}).has_value());
  EXPECT_TRUE(rendezvous_ranking("job", {}).empty());
}

TEST(Rendezvous, ScoreIsStableAcrossBuildsAndHosts) {
  // Workers of different versions must agree: these values are part of the protocol.
  EXPECT_EQ(rendezvous_score("job-1", "host-a/100"), rendezvous_score("job-1", "host-a/100"));
  EXPECT_NE(rendezvous_score("ab", "c"), rendezvous_score("abc", ""));
  EXPECT_NE(rendezvous_score("c", "ab"), rendezvous_score("bc", "a"));
  EXPECT_EQ(rendezvous_score("job-1", "host-a/100"), 0xcb2a276480530e19ull);
}

TEST(Rendezvous, DeterministicWhateverTheOrderOfWorkers) {
  const auto ws = workers(7);
  std::mt19937 rng(3);
  for (const std::string& job : job_ids(200)) {
    const std::string first = owner_of(job, ws);
    auto shuffled = ws;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    EXPECT_EQ(owner_of(job, shuffled), first) << job;
  }
}

TEST(Rendezvous, BalancedOverAThousandJobs) {
  for (int n : {2, 3, 5, 10}) {
    const auto ws = workers(n);
    std::map<std::string, int> load;
    for (const std::string& job : job_ids(1000)) ++load[owner_of(job, ws)];
    ASSERT_EQ(load.size(), static_cast<std::size_t>(n)) << "a worker got no job";
    const double fair = 1000.0 / n;
    for (const auto& [w, count] : load) {
      EXPECT_GT(count, fair * 0.7) << n << " workers, " << w;
      EXPECT_LT(count, fair * 1.3) << n << " workers, " << w;
    }
  }
}

TEST(Rendezvous, OnlyTheLeaversJobsMoveAndToTheirSecondChoice) {
  const auto ws = workers(6);
  const std::string leaver = ws[2];
  auto survivors = ws;
  survivors.erase(survivors.begin() + 2);
  int moved = 0;
  for (const std::string& job : job_ids(1000)) {
    const std::string before = owner_of(job, ws);
    const std::string after = owner_of(job, survivors);
    if (before == leaver) {
      ++moved;
      EXPECT_EQ(after, ws[rendezvous_ranking(job, ws)[1]]) << job;
    } else {
      EXPECT_EQ(after, before) << job;
    }
  }
  EXPECT_GT(moved, 100);  // about 1000/6 jobs were the leaver's
  EXPECT_LT(moved, 240);
}

TEST(Rendezvous, AJoinerTakesOnlyItsShare) {
  const auto ws = workers(4);
  auto more = ws;
  more.push_back("newcomer/1");
  int moved = 0;
  for (const std::string& job : job_ids(1000)) {
    const std::string before = owner_of(job, ws);
    const std::string after = owner_of(job, more);
    if (after != before) {
      ++moved;
      EXPECT_EQ(after, "newcomer/1");
    }
  }
  EXPECT_GT(moved, 140);  // about 1000/5
  EXPECT_LT(moved, 260);
}

TEST(Rendezvous, RankingStartsWithTheOwnerAndListsEveryone) {
  const auto ws = workers(5);
  for (const std::string& job : job_ids(50)) {
    const auto rank = rendezvous_ranking(job, ws);
    ASSERT_EQ(rank.size(), ws.size());
    EXPECT_EQ(rank[0], *rendezvous_owner(job, ws));
    auto sorted = rank;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);
  }
}
