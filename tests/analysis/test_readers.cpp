#include <gtest/gtest.h>

#include "analysis/grain_snapshot.h"
#include "analysis/series.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

const std::string kHeader =
    "time,step,dt,kinetic_energy,elastic_energy,external_work,damping_dissipation,"
    "contact_dissipation,energy_residual,top_fx,top_fy,top_x,top_y,bottom_fx,bottom_fy,"
    "bottom_x,bottom_y\n";

// The message of the sg::Error thrown by f, or "" if none is thrown.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SeriesReader, ParsesAGoodFile) {
  test::ScratchDir dir("series_good");
  const std::string path =
      dir.write("series.csv",
                "# softgrain series\n" + kHeader +
                    "0,0,1e-3,0,0,0,0,0,0,-1.5,10,0,5,1.5,-10,0,-5\n"
                    "0.5,500,1e-3,2.5,1,3,0.75,0.25,-1e-9,-2.5,+12,0.25,5,2.5,-12,-0.25,-5\r\n");
  const Series s = read_series(path);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.columns.size(), 17u);
  EXPECT_EQ(s.body_names, (std::vector<std::string>{"top", "bottom"}));
  EXPECT_EQ(s.column("time")[1], 0.5);
  EXPECT_EQ(s.column("step")[1], 500.0);
  EXPECT_EQ(s.column("top_fy")[1], 12.0);  // a leading '+' is accepted
  EXPECT_EQ(s.column("energy_residual")[1], -1e-9);
  EXPECT_EQ(s.column("bottom_y")[1], -5.0);  // trailing CR of a CRLF file ignored
}

TEST(SeriesReader, MissingColumnNamesFileAndColumn) {
  test::ScratchDir dir("series_missing");
  std::string header = kHeader;
  header.replace(header.find("contact_dissipation,"), 20, "");
  const std::string path = dir.write("series.csv", header + "0,0,1,0,0,0,0,0,1,2,3,4,5,6,7,8\n");
  const std::string message = error_of([&] { read_series(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("missing column 'contact_dissipation'"), std::string::npos) << message;
}

TEST(SeriesReader, IncompleteDrivenBodyIsRefused) {
  test::ScratchDir dir("series_body");
  std::string header = kHeader;
  header.replace(header.find(",bottom_y"), 9, "");
  const std::string path = dir.write("series.csv", header + "0,0,1,0,0,0,0,0,0,1,2,3,4,5,6,7\n");
  const std::string message = error_of([&] { read_series(path); });
  EXPECT_NE(message.find("'bottom_y'"), std::string::npos) << message;
  EXPECT_NE(message.find("'bottom'"), std::string::npos) << message;
}

TEST(SeriesReader, MalformedNumberNamesFileLineAndColumn) {
  test::ScratchDir dir("series_malformed");
  // Line 1 header, line 2 good, line 3 has "1.2.3" in top_fx.
  const std::string path = dir.write("series.csv", kHeader +
                                                       "0,0,1,0,0,0,0,0,0,1,2,3,4,5,6,7,8\n"
                                                       "1,1,1,0,0,0,0,0,0,1.2.3,2,3,4,5,6,7,8\n");
  const std::string message = error_of([&] { read_series(path); });
  EXPECT_NE(message.find(path + ":3:"), std::string::npos) << message;
  EXPECT_NE(message.find("column 'top_fx'"), std::string::npos) << message;
  EXPECT_NE(message.find("'1.2.3'"), std::string::npos) << message;
}

TEST(SeriesReader, EmptyFieldNonFiniteValueAndShortRowAreRefused) {
  test::ScratchDir dir("series_bad");
  const std::string empty = dir.write("a.csv", kHeader + "0,0,1,0,0,0,0,,0,1,2,3,4,5,6,7,8\n");
  EXPECT_NE(error_of([&] { read_series(empty); }).find(":2: column 'contact_dissipation'"),
            std::string::npos);
  const std::string nan = dir.write("b.csv", kHeader + "0,0,1,nan,0,0,0,0,0,1,2,3,4,5,6,7,8\n");
  EXPECT_NE(error_of([&] { read_series(nan); }).find("non-finite"), std::string::npos);
  const std::string shortrow = dir.write("c.csv", kHeader + "0,0,1,0,0\n");
  EXPECT_NE(error_of([&] { read_series(shortrow); }).find(":2: 5 fields, header has 17"),
            std::string::npos);
  const std::string backwards = dir.write("d.csv", kHeader +
                                                       "1,0,1,0,0,0,0,0,0,1,2,3,4,5,6,7,8\n"
                                                       "1,0,1,0,0,0,0,0,0,1,2,3,4,5,6,7,8\n");
  EXPECT_NE(error_of([&] { read_series(backwards); }).find(":3: column 'time'"), std::string::npos);
  EXPECT_NE(error_of([&] { read_series(dir.file("absent.csv")); }).find("cannot open"),
            std::string::npos);
}

TEST(GrainSnapshotReader, ParsesAndChecks) {
  test::ScratchDir dir("snapshot");
  const std::string good = dir.write("g.csv",
                                     "body,x,y,vx,vy,area\n"
                                     "g0,1,2,0.5,-0.5,0.785\n"
                                     "top,0,10,0.5,0,100\n"
                                     "g1,3.5,4,-0.25,0,0.8\n");
  const GrainSnapshot s = read_grain_snapshot(good, 7.0);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s.time, 7.0);
  EXPECT_EQ(s.body[2], "g1");
  EXPECT_EQ(s.position[2], Vec2(3.5, 4.0));
  EXPECT_EQ(s.velocity[0], Vec2(0.5, -0.5));
  EXPECT_EQ(s.area[1], 100.0);
  const GrainSnapshot grains = without_bodies(s, {"top", "bottom"});
  ASSERT_EQ(grains.size(), 2u);
  EXPECT_EQ(grains.body[1], "g1");

  const std::string no_area = dir.write("h.csv", "body,x,y,vx,vy\ng0,1,2,0,0\n");
  EXPECT_NE(error_of([&] { read_grain_snapshot(no_area, 0.0); }).find("missing column 'area'"),
            std::string::npos);
  const std::string negative = dir.write("i.csv", "body,x,y,vx,vy,area\ng0,1,2,0,0,-1\n");
  EXPECT_NE(error_of([&] { read_grain_snapshot(negative, 0.0); }).find(":2: column 'area'"),
            std::string::npos);
}

}  // namespace
}  // namespace sg
