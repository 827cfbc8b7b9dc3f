#include "animkit/io/ik_report.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../support/temp_files.h"
#include "animkit/trajectory/lab_shapes.h"

namespace animkit {
namespace {

class IkReport : public testing::Test {
 protected:
  Chain chain = *build_chain(lab_arm());
  std::vector<Vec3> targets = lab_shape_targets(LabShape::square);
  DrawingOptions options;
  DrawingRun run = *run_drawing(chain, targets, options);
  IkRunLabel label{"square", "ccd", std::nullopt};
};

TEST_F(IkReport, MetricsJsonHasTheContractNames) {
  const auto j = nlohmann::json::parse(ik_metrics_json(label, options, summarize(run)));
  EXPECT_EQ(j["solver"], "ccd");
  EXPECT_EQ(j["shape"], "square");
  EXPECT_EQ(j["targets"], 150);
  EXPECT_EQ(j["converged_fraction"], 1.0);
  EXPECT_EQ(j["unreachable_targets"], 0);
  for (const char* key : {"mean", "median", "max"}) EXPECT_TRUE(j["iterations"].contains(key));
  for (const char* key : {"mean", "max"}) EXPECT_TRUE(j["error"].contains(key));
  EXPECT_LE(j["error"]["max"].get<double>(), 1e-4);
  EXPECT_TRUE(j["max_joint_step_rad"].is_number());
  EXPECT_GT(j["solve_time_us"]["median"].get<double>(), 0.0);
  EXPECT_EQ(j["iterations"]["max"], summarize(run).iterations_max);
}

TEST_F(IkReport, PathCsvHasOneRowPerFrame) {
  std::istringstream csv(ik_path_csv(run));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("frame,target_x,target_y,target_z,end_x,end_y,end_z,iterations,error", 0),
            0u);
  int rows = 0;
  while (std::getline(csv, line)) {
    double values[11];
    std::istringstream fields(line);
    for (double& v : values) {
      std::string field;
      std::getline(fields, field, ',');
      v = std::stod(field);
    }
    EXPECT_EQ(values[0], rows);
    // Round trip at full precision: the file reproduces the run.
    EXPECT_EQ(values[1], run.frames[rows].target.x());
    EXPECT_EQ(values[6], run.frames[rows].end_effector.z());
    EXPECT_EQ(values[7], run.frames[rows].ik.iterations);
    ++rows;
  }
  EXPECT_EQ(rows, 150);
}

TEST_F(IkReport, SvgDrawsGreenTargetsAndARedPathWithATitle) {
  const std::string svg = ik_drawing_svg(label, run);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("<title>square drawn with ccd</title>"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#00cc00\""), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"#e00000\""), std::string::npos);
  std::size_t circles = 0;
  for (auto at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1))
    ++circles;
  EXPECT_EQ(circles, 150u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

// Whether xmllint (Debian's libxml2-utils) reads `svg` as well-formed XML.
bool well_formed_xml(const std::filesystem::path& dir, const std::string& svg) {
  std::ofstream(dir / "drawing.svg", std::ios::binary) << svg;
  const std::string command = "xmllint --noout '" + (dir / "drawing.svg").string() + "'";
  return std::system(command.c_str()) == 0;
}

TEST_F(IkReport, SvgEscapesNamesWithMarkup) {
  // Regression: names were written raw, so "<&\">" made the SVG malformed.
  const auto dir = testing_support::fresh_dir("ik_report_svg_markup");
  for (const std::string shape : {"text <&\">", "curve a&b<c>.csv", "curve it's \xff\x01.csv"}) {
    const std::string svg = ik_drawing_svg({shape, "ccd", std::nullopt}, run);
    EXPECT_TRUE(well_formed_xml(dir, svg)) << shape;
  }
  EXPECT_NE(ik_drawing_svg({"text <&\">", "ccd", std::nullopt}, run)
                .find("<title>text &lt;&amp;&quot;&gt; drawn with ccd</title>"),
            std::string::npos);
}

TEST_F(IkReport, MetricsJsonSurvivesNamesThatAreNotUtf8) {
  // Regression: nlohmann threw type_error 316 on the byte 0xff.
  const IkRunLabel bad{"curve a\xff.csv", "ccd", std::nullopt};
  std::string text;
  ASSERT_NO_THROW(text = ik_metrics_json(bad, options, summarize(run)));
  EXPECT_EQ(nlohmann::json::parse(text)["shape"], "curve a\xef\xbf\xbd.csv");
}

TEST_F(IkReport, WritesAllThreeFiles) {
  const auto dir = testing_support::fresh_dir("ik_report_test");
  ASSERT_TRUE(write_ik_reports(dir / "nested", label, options, run));
  for (const char* name : {"metrics.json", "path.csv", "drawing.svg"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "nested" / name)) << name;
    EXPECT_FALSE(std::filesystem::exists(dir / "nested" / (std::string(name) + ".tmp")));
  }
}

}  // namespace
}  // namespace animkit
