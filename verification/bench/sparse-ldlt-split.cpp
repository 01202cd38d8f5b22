// SPDX-License-Identifier: MIT
// The sparse LDL^T of a split order (two halves and a separator) on one and on two threads: a
// chain of 6-dof nodes coupled to their neighbours, the pattern of a long bridge's deck, of 132
// to 1,086 equations. Each iteration factorises and solves once on one thread and once on two,
// alternating, so that a change of the machine's load hits both alike; the counters are the
// medians of each (microseconds) and the one-thread time over the two-thread time. The two give
// the same bits (SparseLdltTest), so only the time is compared.
#include <benchmark/benchmark.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <vector>

#include "tcl/analysis/system/SparseLdlt.h"

namespace {

using dabs::analysis::SparseLdlt;

Eigen::SparseMatrix<double> deckChain(int nodes) {
  constexpr int ndf = 6;
  const int n = nodes * ndf;
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < nodes; ++k)
    for (int i = 0; i < ndf; ++i)
      for (int j = 0; j < ndf; ++j) {
        const int r = k * ndf + i, c = k * ndf + j;
        t.emplace_back(r, c, i == j ? 10.0 + i + 1 : 0.1 / (1 + i + j));
        if (k + 1 < nodes) {
          t.emplace_back(r, c + ndf, -1.0 / (1 + i + j));
          t.emplace_back(c + ndf, r, -1.0 / (1 + i + j));
        }
      }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

double median(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void BM_SplitLdltOneAndTwoThreads(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = deckChain(static_cast<int>(state.range(0)));
  SparseLdlt ldlt;
  ldlt.analyze(A);
  if (ldlt.split().separator == 0) {
    state.SkipWithError("the order is not split");
    return;
  }
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  Eigen::VectorXd x;
  std::vector<double> times[2];
  for (auto _ : state) {
    for (int threads = 1; threads <= 2; ++threads) {
      ldlt.setThreads(threads);
      const auto start = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(ldlt.factorize(A));
      ldlt.solve(b, x);
      benchmark::DoNotOptimize(x.data());
      const auto stop = std::chrono::steady_clock::now();
      times[threads - 1].push_back(std::chrono::duration<double, std::micro>(stop - start).count());
    }
  }
  const double one = median(times[0]), two = median(times[1]);
  state.counters["equations"] = static_cast<double>(A.rows());
  state.counters["one_thread_us"] = one;
  state.counters["two_threads_us"] = two;
  state.counters["speedup"] = two > 0.0 ? one / two : 0.0;
}
BENCHMARK(BM_SplitLdltOneAndTwoThreads)->Arg(22)->Arg(30)->Arg(45)->Arg(61)->Arg(100)->Arg(181);

}  // namespace

BENCHMARK_MAIN();
