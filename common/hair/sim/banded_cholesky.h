#pragma once
// Cholesky factorisation and solve of a small symmetric positive definite band matrix,
// as LAPACK's dpbsv does, for the strand solver's systems (a few hundred unknowns, 11
// super-diagonals). At that size Debian's reference LAPACK spends much of its time in the
// calls of its BLAS rank-1 updates; this loop (right-looking, its updates independent and
// along memory, the forward substitution riding along) took 7.9 us of CPU against
// dpbsv's 15.4 us for 171 unknowns (medians of 5, three runs,
// build/bin/hair-bench-strand-solver, 2026-11-22), and spares the stages a run-time
// dependency.
// tests/unit/sim/test_banded_cholesky.cpp checks it against dpbsv.

#include <span>

namespace hair {

/// Solves A x = b in place for an n x n SPD band matrix with `bandwidth` super-diagonals,
/// given in LAPACK's upper band storage: A(i, j), i <= j, at band[bandwidth + i - j + j *
/// (bandwidth + 1)]. `band` is overwritten by the factor U (A = U^T U), `rhs` (n values)
/// by x. Returns 0, or k + 1 if the leading minor of order k + 1 is not positive (as
/// LAPACK's info).
int solve_banded_spd(std::span<double> band, std::span<double> rhs, int n, int bandwidth);

}  // namespace hair
