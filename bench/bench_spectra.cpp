// Spectra of mass and momentum (src/spectra): the fast gridded-FFT method at the size it is meant
// for (N = 10^6 particles, all modes |l|, |m| ≤ 128, in under 2 s on one core) and the exact sums
// for scale.
#include <benchmark/benchmark.h>

#include "init/random.hpp"
#include "spectra/spectral_transforms.hpp"

namespace {

using namespace granule;

ParticleState uniform_gas(std::size_t n) {
  Random random(2024);
  ParticleState state;
  state.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    state.x[j] = random.uniform();
    state.y[j] = random.uniform();
    state.vx[j] = random.normal();
    state.vy[j] = random.normal();
  }
  return state;
}

// ρ̃, p̃_x, p̃_y at all (2M+1)² modes; args: N, M, Lees–Edwards (0/1).
void BM_SpectraFast(benchmark::State& bench) {
  const ParticleState state = uniform_gas(static_cast<std::size_t>(bench.range(0)));
  spectra::TransformOptions options;
  options.max_mode = static_cast<int>(bench.range(1));
  const bool sheared = bench.range(2) != 0;
  const ShearFrame frame{1.0, 1.0, sheared ? 1.0 : 0.0};
  for (auto _ : bench) {
    benchmark::DoNotOptimize(spectra::transform_fields(state, frame, sheared ? 0.37 : 0.0, options));
  }
  bench.counters["particles"] = static_cast<double>(state.size());
}
BENCHMARK(BM_SpectraFast)->Args({1000000, 128, 0})->Args({1000000, 128, 1})->Args({40000, 128, 0})
    ->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SpectraExact(benchmark::State& bench) {
  const ParticleState state = uniform_gas(static_cast<std::size_t>(bench.range(0)));
  spectra::TransformOptions options;
  options.max_mode = static_cast<int>(bench.range(1));
  options.method = spectra::SpectralMethod::exact;
  for (auto _ : bench) {
    benchmark::DoNotOptimize(spectra::transform_fields(state, ShearFrame{}, 0.0, options));
  }
}
BENCHMARK(BM_SpectraExact)->Args({10000, 32})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
