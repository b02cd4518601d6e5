// Labelling one level: contactbench's labeller against OpenCV's (Spaghetti, BBDT, SAUF) on the same maps, and
// a memory pass (read the heights, write int32) as the floor. Names:
//   labelling/<impl>/n:<n>/coverage:<pct>/conn:<c>
// impl: contactbench, opencv_spaghetti, opencv_bbdt, opencv_sauf, memory_pass. All on bench::kThreads
// threads. OpenCV's connectedComponents returns labels only; contactbench also returns every spot's area.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_surfaces.hpp"
#include "contactbench/core/labelling.hpp"

#ifdef CB_HAVE_OPENCV
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#endif

namespace contactbench::bench {
namespace {

const Index kSizes[] = {256, 1024, 4096};
const int kCoverages[] = {1, 10, 50};  // percent of points in contact
const Connectivity kConnectivities[] = {Connectivity::four, Connectivity::eight};

void label_with_contactbench(benchmark::State& state, Index n, int coverage, Connectivity connectivity) {
  const BinaryMap& map = contact_map(n, coverage / 100.0);
  Labeller labeller(Topology{connectivity, false, false}, kThreads);
  Index spots = 0;
  for (auto _ : state) {
    const Labelling& result = labeller.label(map);
    spots = result.count;
    benchmark::DoNotOptimize(result.labels.data());
  }
  state.SetItemsProcessed(state.iterations() * n * n);
  state.counters["spots"] = static_cast<double>(spots);
}

#ifdef CB_HAVE_OPENCV
void label_with_opencv(benchmark::State& state, Index n, int coverage, Connectivity connectivity,
                       int algorithm) {
  const BinaryMap& map = contact_map(n, coverage / 100.0);
  cv::setNumThreads(kThreads);
  const cv::Mat image(static_cast<int>(n), static_cast<int>(n), CV_8U, const_cast<std::uint8_t*>(map.data()));
  cv::Mat labels;
  int spots = 0;
  for (auto _ : state) {
    spots = cv::connectedComponents(image, labels, static_cast<int>(connectivity), CV_32S, algorithm) - 1;
    benchmark::DoNotOptimize(labels.data);
  }
  state.SetItemsProcessed(state.iterations() * n * n);
  state.counters["spots"] = spots;
}
#endif

std::string name(const std::string& impl, Index n, int coverage, Connectivity c) {
  return "labelling/" + impl + "/n:" + std::to_string(n) + "/coverage:" + std::to_string(coverage) +
         "/conn:" + std::to_string(static_cast<int>(c));
}

void register_all() {
  for (const Index n : kSizes)
    for (const int coverage : kCoverages)
      for (const Connectivity c : kConnectivities) {
        register_timed(name("contactbench", n, coverage, c), label_with_contactbench, n, coverage, c);
#ifdef CB_HAVE_OPENCV
        const std::pair<const char*, int> opencv[] = {{"opencv_spaghetti", cv::CCL_SPAGHETTI},
                                                      {"opencv_bbdt", cv::CCL_BBDT},
                                                      {"opencv_sauf", cv::CCL_SAUF}};
        for (const auto& [impl, algorithm] : opencv)
          register_timed(name(impl, n, coverage, c), label_with_opencv, n, coverage, c, algorithm);
#endif
        register_timed(name("memory_pass", n, coverage, c), memory_pass, n);
      }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  contactbench::bench::register_all();
#ifdef CB_HAVE_OPENCV
  return contactbench::bench::run_benchmarks(argc, argv, {{"opencv", CV_VERSION}});
#else
  return contactbench::bench::run_benchmarks(argc, argv, {{"opencv", "not installed"}});
#endif
}
