// The field model against the SPL rule book's numbers and hand-computed distances.
#include <gtest/gtest.h>

#include "ringlet/localization/field_model.hpp"

namespace ringlet::localization {
namespace {

TEST(LocalizationField, SplFieldHasItsSeventeenLines) {
  const FieldModel f;
  EXPECT_EQ(f.along_x().size(), 10U);  // 2 touch lines, 4 penalty area sides, 4 goal area sides
  EXPECT_EQ(f.along_y().size(), 7U);   // 2 goal lines, the centre line, 2 penalty and 2 goal area fronts
  EXPECT_DOUBLE_EQ(f.penalty_marks()[1].x, 3.2);
  EXPECT_DOUBLE_EQ(f.goal_posts()[3].y, 0.75);
}

TEST(LocalizationField, DistancesToTheNearestLineOfEachDirection) {
  const FieldModel f;
  EXPECT_DOUBLE_EQ(f.squared_distance_along_y(0.5, 0.0), 0.25);        // the centre line
  EXPECT_NEAR(f.squared_distance_along_y(4.0, 0.0), 0.01, 1e-12);      // the goal area front at 3.9
  EXPECT_DOUBLE_EQ(f.squared_distance_along_x(0.0, 2.5), 0.25);        // the north touch line
  EXPECT_DOUBLE_EQ(f.squared_distance_along_x(5.0, 3.0), 0.25);        // past the touch line's end (4.5, 3)
  EXPECT_NEAR(f.squared_distance_along_x(3.0, 1.9), 0.01, 1e-12);      // a penalty area side at y = 2
  EXPECT_TRUE(f.on_carpet(5.2, 3.7));
  EXPECT_FALSE(f.on_carpet(5.3, 0.0));
}

TEST(LocalizationField, ALabFieldFromItsDimensions) {
  FieldDimensions d;
  d.length = 6.0;
  d.width = 4.0;
  d.penalty_area_width = 3.0;
  d.goal_area_width = 1.6;
  d.centre_circle_radius = 0.5;
  ASSERT_EQ(check(d), "");
  const FieldModel f(d);
  EXPECT_DOUBLE_EQ(f.squared_distance_along_y(3.5, 0.0), 0.25);  // goal line at x = 3
  EXPECT_DOUBLE_EQ(f.squared_distance_along_x(0.0, 2.5), 0.25);  // touch line at y = 2
}

TEST(LocalizationField, CheckNamesTheBadKey) {
  FieldDimensions d;
  d.width = 0.0;
  EXPECT_NE(check(d).find("width"), std::string::npos);
  d = {};
  d.penalty_area_width = 7.0;
  EXPECT_NE(check(d).find("penalty_area_width"), std::string::npos);
  d = {};
  d.goal_area_length = 2.0;
  EXPECT_NE(check(d).find("goal_area_length"), std::string::npos);
}

}  // namespace
}  // namespace ringlet::localization
