// The memo of outside-volume queries: an answer from it is the query's own, bit for bit, from
// any thread and after any eviction.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "index/sov_memo.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

bool sameBits(const OutsideVolume& a, const OutsideVolume& b) {
  return std::memcmp(&a.volume, &b.volume, sizeof(double)) == 0 &&
         std::memcmp(&a.d_radius, &b.d_radius, sizeof(double)) == 0 &&
         std::memcmp(a.gradient.data(), b.gradient.data(), 3 * sizeof(double)) == 0 &&
         a.triangles_tested == b.triangles_tested && a.center == b.center;
}

TEST(SovMemo, AnswersOnlyTheBallItWasGivenEvenAfterEvictions) {
  auto memo = std::make_unique<detail::SovMemo>();
  const int count = static_cast<int>(4 * detail::SovMemo::kSlotCount);
  auto ballOf = [](int i) { return Sphere{Vec3(i, -i, 0.5 * i), 1.0 + i}; };
  for (int i = 0; i < count; ++i) {
    OutsideVolume v;
    v.volume = i;
    memo->store(detail::bitsOf(ballOf(i)), v);
  }
  int found = 0;
  for (int i = 0; i < count; ++i) {
    OutsideVolume v;
    if (!memo->find(detail::bitsOf(ballOf(i)), &v)) continue;
    ++found;
    EXPECT_EQ(v.volume, i);
  }
  EXPECT_GT(found, 0);
  EXPECT_LE(found, static_cast<int>(detail::SovMemo::kSlotCount));
  // The key is the exact bits: -0 is not +0, and a radius one ulp away is another ball.
  OutsideVolume v;
  v.volume = 7.0;
  memo->store(detail::bitsOf(Sphere{Vec3(0.0, 1.0, 2.0), 1.0}), v);
  EXPECT_TRUE(memo->find(detail::bitsOf(Sphere{Vec3(0.0, 1.0, 2.0), 1.0}), &v));
  EXPECT_FALSE(memo->find(detail::bitsOf(Sphere{Vec3(-0.0, 1.0, 2.0), 1.0}), &v));
  EXPECT_FALSE(
      memo->find(detail::bitsOf(Sphere{Vec3(0.0, 1.0, 2.0), std::nextafter(1.0, 2.0)}), &v));
}

TEST(SovMemo, RepeatedQueriesFromManyThreadsEqualAFreshIndex) {
  const Mesh torus = test::makeTorus(1.0, 0.35, 40, 20);
  const SolidIndex fresh(torus), memoised(torus);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.5, 1.5), R(0.05, 1.0);
  std::vector<Sphere> balls(200);
  for (Sphere& s : balls) s = {Vec3(U(rng), U(rng), 0.3 * U(rng)), R(rng)};
  std::vector<OutsideVolume> expected(balls.size());
  for (size_t i = 0; i < balls.size(); ++i) expected[i] = fresh.outsideVolume(balls[i]);
  // Each ball is asked for eight times, in parallel, in an order that interleaves them.
  const size_t asks = 8 * balls.size();
  std::vector<OutsideVolume> got(asks);
  tbb::parallel_for(size_t{0}, asks,
                    [&](size_t k) { got[k] = memoised.outsideVolume(balls[k % balls.size()]); });
  for (size_t k = 0; k < asks; ++k) EXPECT_TRUE(sameBits(got[k], expected[k % balls.size()])) << k;
}

TEST(SovMemo, ForgottenAnswersAreGoneAndComeBackTheSame) {
  detail::CentreMemo memo;
  const auto key = detail::bitsOf(Vec3(1.0, 2.0, 3.0));
  memo.store(key, Containment::kInside);
  Containment c = Containment::kOutside;
  ASSERT_TRUE(memo.find(key, &c));
  memo.clear();
  EXPECT_FALSE(memo.find(key, &c));
  memo.store(key, Containment::kBoundary);
  ASSERT_TRUE(memo.find(key, &c));
  EXPECT_EQ(c, Containment::kBoundary);

  // An index that forgets between two rounds of the same queries answers them alike.
  const SolidIndex index(test::makeTorus(1.0, 0.35, 40, 20));
  const Sphere balls[] = {{Vec3(1.0, 0.0, 0.0), 0.5}, {Vec3(0.0, 0.0, 0.0), 0.9}};
  OutsideVolume before[2];
  for (int i = 0; i < 2; ++i) before[i] = index.outsideVolume(balls[i]);
  index.forgetAnswers();
  for (int i = 0; i < 2; ++i) EXPECT_TRUE(sameBits(index.outsideVolume(balls[i]), before[i]));
  EXPECT_EQ(index.classify(Vec3(1.0, 0.0, 0.0)), Containment::kInside);
}

}  // namespace
}  // namespace sphereset
