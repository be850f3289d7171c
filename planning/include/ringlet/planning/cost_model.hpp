#pragma once
// The cost model c(r°, M, g) of Powers & Balch §II-B: how fast the reactive layer is expected to
// drive from one region to the next. An edge of the region graph costs distance ÷ expected speed.
// This interface is the seam for the learned model (kNN over experiences); the baseline of §III-B
// is BinaryCostModel.
#include <string>

namespace ringlet::planning {

class OccupancyGrid;

/// One region-to-region transition, as a cost model sees it: the two regions, their occupied
/// counts, the centre-to-centre distance and the map (M) for models that look around.
struct RegionTransition {
  int from = -1, to = -1;          // region indices (OccupancyGrid numbering)
  int from_occupied = 0, to_occupied = 0;
  int direction = 0;               // kGridSteps index from `from` to `to`
  double distance = 0.0;           // metres between the region centres
  const OccupancyGrid* map = nullptr;
};

class CostModel {
 public:
  CostModel() = default;
  CostModel(const CostModel&) = delete;
  CostModel& operator=(const CostModel&) = delete;
  virtual ~CostModel() = default;

  /// The expected average speed over the transition, in m/s: 0 when it is not traversable. The
  /// region graph clamps it to top_speed(), so the planner's heuristic stays admissible.
  [[nodiscard]] virtual double expected_speed(const RegionTransition& t) const noexcept = 0;
  /// The robot's top speed (m/s, > 0).
  [[nodiscard]] virtual double top_speed() const noexcept = 0;
};

/// §III-B's baseline: a transition is impassable when either region holds more than
/// `max_occupied` occupied cells, and otherwise driven at top speed.
class BinaryCostModel final : public CostModel {
 public:
  struct Params {
    int max_occupied = 2;   // occupied cells a region may hold and still be driven through
    double top_speed = 2.0;  // m/s

    /// Empty when usable, else what is wrong (names the field).
    [[nodiscard]] std::string validate() const;
  };

  explicit BinaryCostModel(const Params& p) noexcept : params_(p) {}
  [[nodiscard]] double expected_speed(const RegionTransition& t) const noexcept override {
    return t.from_occupied > params_.max_occupied || t.to_occupied > params_.max_occupied ? 0.0 : params_.top_speed;
  }
  [[nodiscard]] double top_speed() const noexcept override { return params_.top_speed; }

 private:
  Params params_;
};

}  // namespace ringlet::planning
