#include <gtest/gtest.h>

#include <cmath>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/types.h"

using namespace ptz_action_server;

namespace
{
constexpr double DEGREE = M_PI / 180.0;

/// What an ideal zoom lens with these wide-end angles shows at \p zoom.
double idealAngle(double wide_end, double zoom)
{
  return 2.0 * std::atan(std::tan(wide_end / 2.0) / zoom);
}
}  // namespace

TEST(FieldOfViewTest, WideEndModelNarrowsAsFocalLengthGrows)
{
  const FieldOfViewModel field_of_view = FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE });
  EXPECT_NEAR(field_of_view.at(1.0).horizontal, 60.0 * DEGREE, 1e-12);
  EXPECT_NEAR(field_of_view.at(1.0).vertical, 34.0 * DEGREE, 1e-12);
  const FieldOfViewAngles at_four = field_of_view.at(4.0);
  EXPECT_NEAR(at_four.horizontal, idealAngle(60.0 * DEGREE, 4.0), 1e-12);
  EXPECT_NEAR(at_four.vertical, idealAngle(34.0 * DEGREE, 4.0), 1e-12);
  // Not the plain division: 2 atan(tan(30 deg) / 4) is 16.4 degrees, not 15.
  EXPECT_GT(at_four.horizontal, 16.0 * DEGREE);
  // Below the wide end it holds the wide end (a device never reports less than 1 X).
  EXPECT_NEAR(field_of_view.at(0.5).horizontal, 60.0 * DEGREE, 1e-12);
  EXPECT_NEAR(field_of_view.at(std::nan("")).horizontal, 60.0 * DEGREE, 1e-12);
}

TEST(FieldOfViewTest, DividedLawIsThePlainDivision)
{
  const FieldOfViewModel divided = FieldOfViewModel::fromWideEnd({ 1.2, 0.7 }, ZoomLaw::DIVIDED);
  EXPECT_NEAR(divided.at(4.0).horizontal, 0.3, 1e-12);
  EXPECT_NEAR(divided.at(4.0).vertical, 0.175, 1e-12);
  EXPECT_NEAR(divided.at(0.2).horizontal, 1.2, 1e-12);
  const FocalScale scale = divided.focalScale(1.0, 4.0);
  EXPECT_NEAR(scale.x, std::tan(0.6) / std::tan(0.15), 1e-12);  // the tangent formula holds for any law
}

TEST(FieldOfViewTest, FocalScaleMatchesTheTangentFormula)
{
  const FieldOfViewModel field_of_view = FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE });
  const FocalScale scale = field_of_view.focalScale(2.0, 6.0);
  const FieldOfViewAngles from = field_of_view.at(2.0);
  const FieldOfViewAngles to = field_of_view.at(6.0);
  EXPECT_NEAR(scale.x, std::tan(from.horizontal / 2.0) / std::tan(to.horizontal / 2.0), 1e-12);
  EXPECT_NEAR(scale.y, std::tan(from.vertical / 2.0) / std::tan(to.vertical / 2.0), 1e-12);
  EXPECT_NEAR(scale.x, 3.0, 1e-12);  // an ideal lens: focal length proportional to X
  EXPECT_NEAR(field_of_view.focalScale(3.0, 3.0).y, 1.0, 1e-12);
}

TEST(FieldOfViewTest, TableInterpolatesFocalLengthAndClampsAtTheEnds)
{
  // Rows of an ideal 60 x 34 degree lens: interpolating the focal length reproduces it between rows.
  std::vector<FieldOfViewRow> rows;
  for (double zoom : { 1.0, 3.0, 10.0 })
  {
    rows.push_back({ zoom, { idealAngle(60.0 * DEGREE, zoom), idealAngle(34.0 * DEGREE, zoom) } });
  }
  const FieldOfViewModel table = FieldOfViewModel::fromTable(rows);
  const FieldOfViewModel model = FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE });
  for (double zoom : { 1.0, 1.7, 3.0, 6.5, 10.0 })
  {
    EXPECT_NEAR(table.at(zoom).horizontal, model.at(zoom).horizontal, 1e-12) << zoom;
    EXPECT_NEAR(table.at(zoom).vertical, model.at(zoom).vertical, 1e-12) << zoom;
  }
  EXPECT_NEAR(table.at(30.0).horizontal, idealAngle(60.0 * DEGREE, 10.0), 1e-12);  // past the last row
  EXPECT_NEAR(table.at(0.5).vertical, 34.0 * DEGREE, 1e-12);

  // A measured, non-ideal table: halfway in zoom is halfway in 1 / tan(fov / 2).
  const FieldOfViewModel measured = FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.6 } }, { 5.0, { 0.3, 0.2 } } });
  const double focal = (1.0 / std::tan(0.5) + 1.0 / std::tan(0.15)) / 2.0;
  EXPECT_NEAR(measured.at(3.0).horizontal, 2.0 * std::atan(1.0 / focal), 1e-12);
  EXPECT_NEAR(measured.focalScale(1.0, 5.0).x, std::tan(0.5) / std::tan(0.15), 1e-12);
}

TEST(FieldOfViewTest, OneRowTableHoldsItsAngles)
{
  const FieldOfViewModel fixed = FieldOfViewModel::fromTable({ { 1.0, { 1.2, 0.7 } } });
  EXPECT_NEAR(fixed.at(12.0).horizontal, 1.2, 1e-12);
  EXPECT_NEAR(fixed.focalScale(1.0, 12.0).x, 1.0, 1e-12);
}

TEST(FieldOfViewTest, ZoomForUndoesAtForBothLaws)
{
  const FieldOfViewModel lens = FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE });
  const FieldOfViewModel divided = FieldOfViewModel::fromWideEnd({ 1.2, 0.7 }, ZoomLaw::DIVIDED);
  for (const FieldOfViewModel* model : { &lens, &divided })
  {
    for (double zoom : { 1.0, 1.3, 4.0, 12.5, 36.0 })
    {
      const FieldOfViewAngles angles = model->at(zoom);
      EXPECT_NEAR(model->zoomFor(angles.horizontal, ViewDirection::HORIZONTAL), zoom, 1e-9 * zoom) << zoom;
      EXPECT_NEAR(model->zoomFor(angles.vertical, ViewDirection::VERTICAL), zoom, 1e-9 * zoom) << zoom;
    }
    // Wider than the wide end: the widest there is.
    EXPECT_DOUBLE_EQ(model->zoomFor(model->at(1.0).horizontal + 0.1, ViewDirection::HORIZONTAL), 1.0);
  }
  // The laws differ: the lens needs less zoom than the division for the same narrow angle (tan grows faster).
  EXPECT_NEAR(divided.zoomFor(0.3, ViewDirection::HORIZONTAL), 4.0, 1e-12);
  EXPECT_NEAR(lens.zoomFor(15.0 * DEGREE, ViewDirection::HORIZONTAL), std::tan(30.0 * DEGREE) / std::tan(7.5 * DEGREE),
              1e-12);
}

TEST(FieldOfViewTest, ZoomForWalksATableAndStopsAtItsEnds)
{
  // Non-ideal rows, starting above 1 X, with a horizontal angle that stays flat from 2 X to 4 X.
  const FieldOfViewModel table = FieldOfViewModel::fromTable(
      { { 1.5, { 1.0, 0.6 } }, { 2.0, { 0.5, 0.3 } }, { 4.0, { 0.5, 0.2 } }, { 6.0, { 0.25, 0.1 } } });
  for (double zoom : { 1.5, 1.8, 2.0, 3.0, 4.0, 4.5, 6.0 })
  {
    EXPECT_NEAR(table.zoomFor(table.at(zoom).vertical, ViewDirection::VERTICAL), zoom, 1e-9) << zoom;
  }
  for (double zoom : { 1.5, 1.8, 4.7, 6.0 })
  {
    EXPECT_NEAR(table.zoomFor(table.at(zoom).horizontal, ViewDirection::HORIZONTAL), zoom, 1e-9) << zoom;
  }
  // The flat span: the largest zoom that still shows 0.5 rad.
  EXPECT_NEAR(table.zoomFor(0.5, ViewDirection::HORIZONTAL), 4.0, 1e-12);
  // Outside the table: its first row's zoom for a wider view, its last for a narrower one.
  EXPECT_DOUBLE_EQ(table.zoomFor(1.4, ViewDirection::HORIZONTAL), 1.5);
  EXPECT_DOUBLE_EQ(table.zoomFor(0.01, ViewDirection::VERTICAL), 6.0);
  // A one-row table has a single zoom.
  const FieldOfViewModel fixed = FieldOfViewModel::fromTable({ { 1.0, { 1.2, 0.7 } } });
  EXPECT_DOUBLE_EQ(fixed.zoomFor(0.2, ViewDirection::HORIZONTAL), 1.0);
}

TEST(FieldOfViewTest, ZoomShowingKeepsBothAnglesInView)
{
  const FieldOfViewModel lens = FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE });
  // A span relatively wider than the view: its horizontal angle decides; one relatively taller: its vertical one.
  for (const FieldOfViewAngles span : { FieldOfViewAngles{ 0.2, 0.05 }, FieldOfViewAngles{ 0.05, 0.2 } })
  {
    const double zoom = lens.zoomShowing(span);
    const FieldOfViewAngles view = lens.at(zoom);
    EXPECT_GE(view.horizontal, span.horizontal - 1e-12);
    EXPECT_GE(view.vertical, span.vertical - 1e-12);
    EXPECT_NEAR(std::min(view.horizontal - span.horizontal, view.vertical - span.vertical), 0.0, 1e-12);
  }
  EXPECT_DOUBLE_EQ(lens.zoomShowing({ 0.2, 0.05 }), lens.zoomFor(0.2, ViewDirection::HORIZONTAL));
  EXPECT_DOUBLE_EQ(lens.zoomShowing({ 0.05, 0.2 }), lens.zoomFor(0.2, ViewDirection::VERTICAL));
  // A missing angle does not count; with none there is no answer.
  EXPECT_DOUBLE_EQ(lens.zoomShowing({ 0.2, std::nan("") }), lens.zoomFor(0.2, ViewDirection::HORIZONTAL));
  EXPECT_TRUE(std::isnan(lens.zoomShowing({ std::nan(""), 0.0 })));
}

TEST(FieldOfViewTest, ZoomForRefusesAnglesOutsideZeroToPi)
{
  const FieldOfViewModel lens = FieldOfViewModel::fromWideEnd({ 1.0, 0.6 });
  const FieldOfViewModel table = FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.6 } }, { 5.0, { 0.3, 0.2 } } });
  for (double angle : { 0.0, -0.1, M_PI, 4.0, std::nan(""), HUGE_VAL })
  {
    EXPECT_TRUE(std::isnan(lens.zoomFor(angle, ViewDirection::HORIZONTAL))) << angle;
    EXPECT_TRUE(std::isnan(table.zoomFor(angle, ViewDirection::VERTICAL))) << angle;
  }
}

TEST(FieldOfViewTest, BadModelsAreRefused)
{
  EXPECT_THROW(FieldOfViewModel::fromWideEnd({ 0.0, 0.5 }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromWideEnd({ 1.0, M_PI }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromWideEnd({ std::nan(""), 0.5 }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromTable({}), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromTable({ { 0.5, { 1.0, 0.5 } } }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.5 } }, { 1.0, { 0.9, 0.4 } } }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.5 } }, { 2.0, { 1.1, 0.4 } } }), ConfigError);
  EXPECT_THROW(FieldOfViewModel::fromTable({ { 1.0, { 1.0, 4.0 } } }), ConfigError);
  try
  {
    FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.5 } }, { 3.0, { 0.5, 0.3 } }, { 2.0, { 0.4, 0.2 } } });
    FAIL() << "an unordered table was taken";
  }
  catch (const ConfigError& error)
  {
    EXPECT_NE(std::string(error.what()).find("row 2"), std::string::npos) << error.what();
  }
}
