// hair-sim-report: how simulated guides keep their groom (docs/simulate.md): each guide's
// tip drift in the head's frame, as a share of its length (mean, 95th percentile and
// largest at the last frame; largest over all frames), and the guides that flipped over
// their root; with --tail, how the guides of the cluster with the most guides (a
// ponytail's tail) hold together: their spread at three quarters of their length over
// their spread at rest, median and largest over the frames; with --stability, a run's
// stability figures for bench/stability.sh on one line (run_stability.h). One Markdown
// table row, or the header with --header.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "hair/core/error.h"
#include "hair/h5/dataset.h"
#include "hair/h5/file.h"
#include "hair/sim/guide_motion_measures.h"
#include "hair/sim/guides_io.h"
#include "hair/sim/run_stability.h"

int main(int argc, char** argv) {
  CLI::App app("Measure how simulated guides keep their groom.", "hair-sim-report");
  std::string guides_path, name;
  bool header = false, tail = false, stability = false, energies = false;
  double stretch_bound = 0.011, inside_bound = 0.05;
  int cluster = -1;
  double fraction = 0.75;
  app.add_flag("--header", header, "print the table's header and exit");
  app.add_flag("--tail", tail,
               "the spread of a bundle of guides at 3/4 of their length instead of the drift");
  app.add_flag("--stability", stability,
               "a run's stability figures on one line, space-separated: frames, finite (1/0), "
               "largest stretch, deepest penetration (mm), most left inside (%), fastest "
               "particle (m/s), total energy first / last / largest (J), kinetic energy's "
               "largest in the middle / last third (J), growth, spring deformation (mm), verdict");
  app.add_flag("--energies", energies,
               "every frame's energies, a line each: frame, kinetic, elastic, gravity, total (J)");
  app.add_option("--stretch-bound", stretch_bound, "--stability: the largest stretch allowed");
  app.add_option("--inside-bound", inside_bound,
                 "--stability: the largest share of particles left inside allowed");
  app.add_option("--cluster", cluster, "--tail: the cluster (default: the one with most guides)");
  app.add_option("--fraction", fraction, "--tail: where along the guides (default 0.75)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("GUIDES_H5", guides_path, "guides.h5 from the simulate stage");
  app.add_option("--name", name, "first column (default: the guides file)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-sim-report: error: " << e.what() << "\n";
    return 2;
  }
  if (header && tail) {
    std::printf(
        "| model | cluster | guides | spread at rest (mm) | spread over rest: median / largest "
        "| at the last frame |\n|---|---:|---:|---:|---|---:|\n");
    return 0;
  }
  if (header) {
    std::printf(
        "| model | guides | frames | tip drift at the end: mean / p95 / max (of length) | most "
        "over the frames | flipped over the root |\n|---|---:|---:|---|---:|---:|\n");
    return 0;
  }
  try {
    if (guides_path.empty()) throw hair::Error::usage("GUIDES_H5 is required");
    const hair::SimulatedGuides guides =
        hair::read_simulated_guides(hair::h5::File::open_read_only(guides_path));
    const std::string label = name.empty() ? guides_path : name;
    if (energies) {
      const hair::h5::File file = hair::h5::File::open_read_only(guides_path);
      (void)hair::read_simulated_guides(file);  // checks the schema
      const auto kinetic = hair::h5::read_vector<double>(file, "/frames/kinetic_energy_j");
      const auto elastic = hair::h5::read_vector<double>(file, "/frames/elastic_energy_j");
      const auto gravity = hair::h5::read_vector<double>(file, "/frames/gravity_energy_j");
      for (size_t f = 0; f < kinetic.size(); ++f)
        std::printf("%zu %.9e %.9e %.9e %.9e\n", f, kinetic[f], elastic[f], gravity[f],
                    kinetic[f] + elastic[f] + gravity[f]);
      return 0;
    }
    if (stability) {
      const hair::RunStability r = hair::run_stability(
          hair::h5::File::open_read_only(guides_path), stretch_bound, inside_bound);
      std::printf("%lld %d %.4f %.1f %.2f %.2f %.3e %.3e %.3e %.3e %.3e %.2f %.2f %s\n",
                  static_cast<long long>(r.frames), r.finite ? 1 : 0, r.max_stretch,
                  r.max_penetration_m * 1e3, r.max_inside * 100, r.max_speed_m_s,
                  r.first_total_j, r.last_total_j, r.max_total_j, r.middle_kinetic_j,
                  r.last_kinetic_j, r.growth, r.deformation_m * 1e3, r.verdict.c_str());
      return 0;
    }
    if (tail) {
      const hair::BundleSpread b = hair::bundle_spread(guides, cluster, fraction);
      if (b.guides < 2) throw hair::Error::usage("the cluster has fewer than two guides");
      std::printf("| %s | %d | %lld | %.1f | %.2f / %.2f | %.2f |\n", label.c_str(), b.cluster,
                  static_cast<long long>(b.guides), 1e3 * b.rest_spread_m, b.median, b.largest,
                  b.ratio.back());
      return 0;
    }
    const hair::DriftSummary s = hair::summarise_drift(hair::guide_drift(guides));
    std::printf("| %s | %lld | %d | %.2f%% / %.2f%% / %.2f%% | %.2f%% | %lld |\n",
                label.c_str(), static_cast<long long>(s.guides),
                guides.frame_count, 100 * s.mean, 100 * s.p95, 100 * s.largest,
                100 * s.largest_any_frame, static_cast<long long>(s.flipped));
  } catch (const hair::Error& error) {
    std::cerr << "hair-sim-report: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
