// Input delay from data: how long after a command the plant responds. Three estimators:
//  - CrossCorrelationDelay: the lag of the peak cross-correlation between each input's
//    increments and the increments of the state derivatives it drives.
//  - ScanDelay: the reference report's brute-force scan (its Fig. 3.6): for every whole number
//    of samples n up to the limit, the inputs are shifted by n and an equation-error model
//    x' = Theta(x, u(t - n dt)) w is fitted by least squares on a library of candidate terms
//    (regressor_library.h); the delay with the smallest mean (1 - R^2) over the states wins.
//    Per-input delays by coordinate sweeps of the same scan.
//  - ContinuousDelay: a bounded minimisation of any cost of the delays (e.g. the simulation
//    error of a model) with NLopt: a global DIRECT-L search, then a local Sbplx refinement.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "preprocessing/regressor_library.h"

namespace usvid {

// States (smoothed), their derivatives and the inputs on one uniform grid of spacing dt.
struct DelayProblem {
  double dt = 0.05;
  std::vector<NamedSignal> states;
  std::vector<NamedSignal> derivatives;  // one per state, same order
  std::vector<NamedSignal> inputs;
  LibraryOptions library;
};

struct DelayEstimate {
  double delay_s = 0.0;             // common delay
  std::vector<double> per_input_s;  // one per input
  std::string method;
  std::vector<double> scan_delays_s;  // the scan, when there is one
  std::vector<double> scan_cost;
};

DelayEstimate CrossCorrelationDelay(const DelayProblem& problem, double max_delay_s);
DelayEstimate ScanDelay(const DelayProblem& problem, double max_delay_s, bool per_input = false);

// cost(delays) for `count` delays in [0, max_delay_s]; `start` seeds the local search.
DelayEstimate ContinuousDelay(const std::function<double(const std::vector<double>&)>& cost,
                              int count, double max_delay_s, const std::vector<double>& start,
                              int max_evaluations = 200);

}  // namespace usvid
