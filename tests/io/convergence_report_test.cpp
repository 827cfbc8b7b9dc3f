// The convergence study's files: the line plot (SVG and image), the table and the curves.
#include "animkit/io/convergence_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support/temp_files.h"
#include "animkit/io/png.h"

namespace animkit {
namespace {

// Two solvers, two steps each, made by hand.
ConvergenceStudy hand_made_study() {
  ConvergenceStudy study;
  study.dt = 1.0 / 60.0;
  study.tolerance = 1e-4;
  const auto step = [](double ms, std::vector<CurvePoint> curve) {
    const int iterations = static_cast<int>(curve.size()) - 1;
    return StudyStep{std::move(curve), ms, iterations, true, 1e-4};
  };
  SolverStudy pcg{"implicit-pcg",
                  {step(2.0, {{0, 1}, {0.5, 1e-2}, {1.5, 5e-5}}),
                   step(3.0, {{0, 1}, {1.0, 1e-1}, {2.0, 1e-3}, {2.8, 1e-7}})},
                  {}};
  SolverStudy vbd{"vbd", {step(1.0, {{0, 1}, {0.9, 9e-5}}), step(1.2, {{0, 1}, {1.1, 8e-5}})}, {}};
  pcg.summary = summarize_study(pcg.steps);
  vbd.summary = summarize_study(vbd.steps);
  study.solvers = {pcg, vbd};
  return study;
}

bool has_pixel(const Image& image, PlotColor c) {
  for (const Pixel& p : image.pixels) {
    if (p.r == c.r && p.g == c.g && p.b == c.b) return true;
  }
  return false;
}

TEST(ConvergenceReport, PlotHasLogAxisToTheToleranceAndOneBoldCurvePerSolver) {
  const LinePlot plot = convergence_plot(hand_made_study(), "test");
  EXPECT_FALSE(plot.validate());
  EXPECT_TRUE(plot.y.log10);
  EXPECT_DOUBLE_EQ(plot.y.min, 1e-5);  // a decade below the tolerance
  EXPECT_EQ(plot.y.max, 1.0);
  EXPECT_EQ(plot.x.min, 0.0);
  EXPECT_GE(plot.x.max, 2.8);
  // Four thin step curves, the dashed tolerance, two bold median curves.
  ASSERT_EQ(plot.series.size(), 7u);
  EXPECT_TRUE(plot.series[4].dashed);
  EXPECT_GT(plot.series[5].width, plot.series[0].width);
  ASSERT_EQ(plot.legend.size(), 3u);
  EXPECT_EQ(plot.legend[0].label, "implicit-pcg  2.50 ms");
  EXPECT_EQ(plot.legend[1].label, "vbd  1.10 ms");
  EXPECT_NE(integrator_color("vbd").g, integrator_color("implicit-pcg").g);
}

TEST(ConvergenceReport, SvgAndImageShowTheSamePlot) {
  const LinePlot plot = convergence_plot(hand_made_study(), "a <study> & more");
  const std::string svg = line_plot_svg(plot);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(svg.find("a &lt;study&gt; &amp; more"), std::string::npos);
  EXPECT_NE(svg.find(">10⁻⁴</text>"), std::string::npos);  // decade labels
  EXPECT_NE(svg.find(">1</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);

  const auto image = line_plot_image(plot);
  ASSERT_TRUE(image.has_value()) << image.error().message;
  EXPECT_EQ(image->width, plot.width);
  EXPECT_EQ(image->height, plot.height);
  EXPECT_TRUE(has_pixel(*image, integrator_color("implicit-pcg")));  // the bold curves' full colour
  EXPECT_TRUE(has_pixel(*image, integrator_color("vbd")));
  EXPECT_TRUE(has_pixel(*image, {40, 40, 40}));  // the frame and the text
}

TEST(ConvergenceReport, BadPlotsAreRefused) {
  LinePlot plot = convergence_plot(hand_made_study(), "t");
  plot.y.min = 0.0;
  EXPECT_EQ(plot.validate()->message, "y axis is logarithmic but its minimum 0 is not positive");
  EXPECT_FALSE(line_plot_image(plot).has_value());
  plot = convergence_plot(hand_made_study(), "t");
  plot.series[1].points[1].y() = std::nan("");
  EXPECT_EQ(plot.validate()->message, "plot series 1 has a non-finite point");
  plot = convergence_plot(hand_made_study(), "t");
  plot.width = 10;
  EXPECT_EQ(plot.validate()->message,
            "plot size must be between 320 and 4096 pixels per side, got 10 x 620");
}

TEST(ConvergenceReport, TableCurvesAndJson) {
  const ConvergenceStudy study = hand_made_study();
  EXPECT_EQ(convergence_table_markdown(study),
            "| solver | median ms/step | max ms/step | median iterations/step | converged steps |\n"
            "|---|---:|---:|---:|---:|\n"
            "| implicit-pcg | 2.50 | 3.00 | 2.5 | 100% |\n"
            "| vbd | 1.10 | 1.20 | 1 | 100% |\n");
  const std::string csv = convergence_curves_csv(study);
  EXPECT_EQ(csv.rfind("solver,step,iteration,ms,relative_gradient\nimplicit-pcg,1,0,0,1\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 + 4 + 2 + 2);
  const auto j = nlohmann::json::parse(convergence_study_json(study, "lab"));
  EXPECT_EQ(j["scene"], "lab");
  EXPECT_EQ(j["solvers"][1]["integrator"], "vbd");
  EXPECT_EQ(j["solvers"][0]["steps"][1]["curve"].size(), 4u);
  EXPECT_EQ(j["solvers"][0]["summary"]["median_step"], 0);
}

TEST(ConvergenceReport, WritesFiveFiles) {
  const auto dir = testing_support::fresh_dir("convergence_report");
  ASSERT_TRUE(write_convergence_report(dir, hand_made_study(), "t", "lab").has_value());
  for (const char* name : {"convergence.svg", "table.md", "curves.csv", "study.json"})
    EXPECT_FALSE(testing_support::read_file(dir / name).empty()) << name;
  const auto png = read_image(dir / "convergence.png");
  ASSERT_TRUE(png.has_value()) << png.error().message;
  EXPECT_EQ(png->width, 1000);
}

}  // namespace
}  // namespace animkit
