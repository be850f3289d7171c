// After construction, the filter's cycle side allocates nothing: predict, correct (resampling
// and sensor resetting included), the estimate, a reset.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "ringlet/localization/particle_filter.hpp"
#include "ringlet/localization/synthetic_view.hpp"

namespace ringlet::localization {
namespace {

TEST(LocalizationNoAllocation, PredictCorrectResampleAndResetAllocateNothing) {
  const FieldModel field;
  ParticleFilter filter(field, FilterParams{});
  hal::SplitMix64 rng(3);
  const std::uint64_t before = ringlet::test::allocations();
  filter.reset_uniform();
  std::size_t injected = 0;
  for (int i = 0; i < 50; ++i) {
    filter.predict({0.02, 0.0, 0.01});
    filter.correct(synthetic_view(field, {-1.0 + 0.02 * i, 0.5, 1.4}, ViewParams{.false_line = 0.3}, rng));
    injected += filter.last_injected();
  }
  filter.reset_to({0.0, 0.0, 0.0}, 0.1, 0.1);
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_GT(injected, 0U) << "sensor resetting ran";
  EXPECT_TRUE(filter.estimate().initialised);
}

}  // namespace
}  // namespace ringlet::localization
