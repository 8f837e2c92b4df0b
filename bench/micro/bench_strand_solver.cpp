// Google Benchmark of the strand solver's pieces on a strand like a long MakeHuman guide
// (30 hair particles, straight, so a ghost per segment: 59 particles, 171 unknowns):
// the band Cholesky solve, ours against LAPACK's dpbsv, and one whole strand step.
//   build/bin/hair-bench-strand-solver --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <vector>

#include "hair/sim/altitude_strand.h"
#include "hair/sim/banded_cholesky.h"
#include "hair/sim/strand_dynamics.h"
#include "hair/sim/strand_stiffness.h"

extern "C" void dpbsv_(const char* uplo, const int* n, const int* kd, const int* nrhs, double* ab,
                       const int* ldab, double* b, const int* ldb, int* info);

namespace {

using Vec3 = Eigen::Vector3d;

hair::AltitudeStrand long_strand() {
  std::vector<Vec3> points;
  for (int i = 0; i < 30; ++i) points.emplace_back(0.01 * i, -0.024 * i, 0.003 * i);
  return hair::build_hair_strand(points, hair::StrandStiffness(hair::StrandMaterial{}));
}

/// The band matrix and right-hand side of one step of the strand, captured by solving it.
struct BandSystem {
  std::vector<double> band, rhs;
  int n = 0, kd = 11;
};
BandSystem band_system() {
  // A diagonally dominant SPD band matrix of the strand's size and band.
  BandSystem system;
  system.n = 3 * 57;
  int ldab = system.kd + 1;
  system.band.assign(static_cast<size_t>(ldab * system.n), 0.0);
  system.rhs.assign(static_cast<size_t>(system.n), 1.0);
  for (int j = 0; j < system.n; ++j) {
    for (int i = std::max(0, j - system.kd); i < j; ++i)
      system.band[static_cast<size_t>(system.kd + i - j + j * ldab)] = 0.1 * ((i + j) % 7 - 3);
    system.band[static_cast<size_t>(system.kd + j * ldab)] = 10.0;
  }
  return system;
}

void BM_BandSolveOurs(benchmark::State& state) {
  const BandSystem system = band_system();
  std::vector<double> band, rhs;
  for (auto _ : state) {
    band = system.band;
    rhs = system.rhs;
    benchmark::DoNotOptimize(hair::solve_banded_spd(band, rhs, system.n, system.kd));
    benchmark::DoNotOptimize(rhs.data());
  }
}
BENCHMARK(BM_BandSolveOurs);

void BM_BandSolveLapack(benchmark::State& state) {
  const BandSystem system = band_system();
  std::vector<double> band, rhs;
  int ldab = system.kd + 1, nrhs = 1, info = 0;
  for (auto _ : state) {
    band = system.band;
    rhs = system.rhs;
    dpbsv_("U", &system.n, &system.kd, &nrhs, band.data(), &ldab, rhs.data(), &system.n, &info);
    benchmark::DoNotOptimize(rhs.data());
  }
}
BENCHMARK(BM_BandSolveLapack);

void BM_StrandStep(benchmark::State& state) {
  const hair::AltitudeStrand strand = long_strand();
  hair::StrandState start;
  start.position_m = strand.rest_m;
  start.velocity_m_s.assign(strand.rest_m.size(), Vec3::Zero());
  hair::StrandStepper stepper;
  hair::StrandState current = start;
  int steps = 0;
  for (auto _ : state) {
    stepper.step(strand, hair::StrandMaterial{}, {}, Vec3(0, -9.81, 0), {}, 1.0 / 60, current);
    if (++steps == 120) {  // keep it swinging, not settled
      current = start;
      steps = 0;
    }
  }
  state.counters["particles"] = strand.particle_count();
}
BENCHMARK(BM_StrandStep);

}  // namespace

BENCHMARK_MAIN();
