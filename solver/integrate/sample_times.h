// The output times of a run: an explicit list, or a uniform grid generated on demand (a long
// run at a fine interval must not hold every time in memory before its first step).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <vector>

namespace limber::integrate {

// Most samples a run may ask for: bounds the index arithmetic and keeps a typo in the end time
// or the interval from asking for a results file of petabytes.
inline constexpr double kMaxSamples = 1e8;

// The checks of SampleTimes::uniform without building anything. Throws InputError (no
// location: callers that have one catch and place it) unless dt > 0, t_end ≥ t0 is finite and
// the samples number at most kMaxSamples.
void check_sample_times(double t0, double t_end, double dt);

class SampleTimes {
 public:
  // An explicit list. Throws InputError unless it is non-empty and strictly increasing.
  SampleTimes(std::vector<double> times);  // NOLINT(google-explicit-constructor): a list is times
  SampleTimes(std::initializer_list<double> times) : SampleTimes(std::vector<double>(times)) {}

  // t0, t0 + dt, ..., up to t_end (the last is t_end itself, even when dt does not divide the
  // span; a last interval shorter than 1e-9 dt is merged into the one before). The times are
  // multiples of dt (no accumulated round-off), computed when asked. Throws as
  // check_sample_times.
  static SampleTimes uniform(double t0, double t_end, double dt);

  std::size_t size() const { return size_; }
  double operator[](std::size_t i) const;
  double front() const { return (*this)[0]; }
  double back() const { return (*this)[size_ - 1]; }

 private:
  SampleTimes(double t0, double t_end, double dt, std::size_t size)
      : t0_(t0), t_end_(t_end), dt_(dt), size_(size) {}

  std::vector<double> list_;  // empty for a uniform grid
  double t0_ = 0.0, t_end_ = 0.0, dt_ = 0.0;
  std::size_t size_ = 0;
};

// The uniform grid of SampleTimes::uniform as a list, for callers that keep the times.
std::vector<double> uniform_sample_times(double t0, double t_end, double dt);

}  // namespace limber::integrate
