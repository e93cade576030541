// How long two cores take to pass a cache line back and forth, for the benchmarks' headers.
//
// A virtual machine's two cores may sit next to each other on the host (one core complex: a round
// trip of about 60 ns measured here) or apart (about 350 ns), and the host moves them while a
// benchmark runs. Everything the solver's threads share crosses between the cores, so the 210
// pyramid on two threads ran 0.52 ms a step at 60 ns and 0.84 at 350 ns (one thread: 0.82 either
// way). The benchmarks print this figure at the start and the end of their runs, and beside each
// scene, so that a figure can be read with the cores it had.
#pragma once

namespace impulse::bench {

// Median of three rounds of up to 20,000 round trips of one cache line (30 ms at most each) between
// two threads pinned to the first two CPUs this process may use, in nanoseconds; -1 with fewer
// than two.
double core_round_trip_ns();

}  // namespace impulse::bench
