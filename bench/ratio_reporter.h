#pragma once
// A console reporter that also remembers each benchmark's counters, so a benchmark program can
// print "baseline / ours" ratios measured in the same run.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

namespace animkit::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      // With repetitions, keep the median aggregate; otherwise the single run.
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      // Keyed "BM_Name" or "BM_Name/arg:value/...", without repetition or aggregate suffixes.
      std::string key = run.run_name.function_name;
      if (!run.run_name.args.empty()) key += "/" + run.run_name.args;
      auto& counters = results_[key];
      for (const auto& [name, counter] : run.counters) counters[name] = counter.value;
      counters["time"] = run.GetAdjustedRealTime();  // per iteration, in the run's time unit
    }
  }

  /// Prints numerator / denominator of the named counter ("time": real time per iteration),
  /// if both benchmarks ran.
  void print_ratio(const std::string& numerator, const std::string& denominator,
                   const std::string& counter, const std::string& label) const {
    const auto a = results_.find(numerator), b = results_.find(denominator);
    if (a == results_.end() || b == results_.end()) return;
    const auto ca = a->second.find(counter), cb = b->second.find(counter);
    if (ca == a->second.end() || cb == b->second.end() || cb->second == 0.0) return;
    std::printf("ratio  %-55s %8.2fx\n", label.c_str(), ca->second / cb->second);
  }

 private:
  std::map<std::string, std::map<std::string, double>> results_;
};

}  // namespace animkit::bench
