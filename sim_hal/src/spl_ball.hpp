#pragma once
// The SPL ball's pattern: white, with a black pentagon round each of the twelve vertices of an
// icosahedron (the black faces of a truncated icosahedron, the classic football).
#include <array>
#include <cmath>

#include "render_math.hpp"

namespace ringlet::sim_hal::detail {

class BallPattern {
 public:
  BallPattern() noexcept {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const double n = 1.0 / std::sqrt(1.0 + phi * phi);
    std::size_t k = 0;
    for (int s1 = -1; s1 <= 1; s1 += 2) {
      for (int s2 = -1; s2 <= 1; s2 += 2) {
        const double a = s1 * n;
        const double b = s2 * phi * n;
        vertices_[k++] = {0.0, a, b};
        vertices_[k++] = {a, b, 0.0};
        vertices_[k++] = {b, 0.0, a};
      }
    }
    // Each vertex's five neighbours are the ones at the icosahedron's edge angle (cos = 1/sqrt 5).
    for (std::size_t i = 0; i < 12; ++i) {
      std::size_t m = 0;
      for (std::size_t j = 0; j < 12 && m < 5; ++j) {
        if (j != i && dot(vertices_[i], vertices_[j]) > 0.3) neighbours_[i][m++] = static_cast<std::uint8_t>(j);
      }
    }
  }

  /// Whether the unit direction n from the ball's centre (in the ball's own frame) is on a black
  /// patch: nearest vertex c, and n farther than kMargin (in cosine) from every edge bisector
  /// between c and a neighbour, which cuts a pentagon round c.
  [[nodiscard]] bool black(const Vec3& n) const noexcept {
    std::size_t best = 0;
    double best_dot = -2.0;
    for (std::size_t i = 0; i < 12; ++i) {
      const double d = dot(n, vertices_[i]);
      if (d > best_dot) {
        best_dot = d;
        best = i;
      }
    }
    for (const std::uint8_t j : neighbours_[best]) {
      if (best_dot - dot(n, vertices_[j]) < kMargin) return false;
    }
    return true;
  }

 private:
  static constexpr double kMargin = 0.30;  // pentagons about as wide as the real ball's
  std::array<Vec3, 12> vertices_{};
  std::array<std::array<std::uint8_t, 5>, 12> neighbours_{};
};

}  // namespace ringlet::sim_hal::detail
