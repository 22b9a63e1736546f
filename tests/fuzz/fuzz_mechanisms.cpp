// The mechanism fuzz (docs/fuzzing.md "Generated mechanisms"): generated mechanisms
// (mechanism_generator.h), seed after seed, each run 0.1 s with IDA and with generalized-α
// through `limber run`'s path (mechanism_run_path.h), until a time budget or a count is spent.
//
//   fuzz_mechanisms [--seconds S] [--first-seed N] [--count N] [--out DIR] [--keep 1]
//   fuzz_mechanisms --print N        (the case of seed N on stdout, not run)
//
// Each case is written to DIR/seed-<N>.yaml before it runs and removed (unless --keep 1) when
// both runs end as expected; one that breaks a rule is kept as DIR/finding-seed-<N>.yaml. The seed is printed
// (and flushed) before each case, so a crash or hang names it and leaves its file behind; a case
// still running after kHangSeconds ends the program (exit 3). Prints the counts by integrator and
// outcome; exit 1 when a finding was kept, 0 otherwise.
#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>

#include "mechanism_generator.h"
#include "mechanism_run_path.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

// Far above a case's two run budgets (the generator's max_wall) plus its reduction.
constexpr int kHangSeconds = 60;

struct Options {
  double seconds = 30.0;
  std::uint64_t first_seed = 1;
  long count = -1;  // no bound
  fs::path out = "out/fuzz-mechanisms";
  bool keep = false;  // keep every case file, not only findings
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--seconds") options.seconds = std::stod(value);
    else if (key == "--first-seed") options.first_seed = std::stoull(value);
    else if (key == "--count") options.count = std::stol(value);
    else if (key == "--out") options.out = value;
    else if (key == "--keep") options.keep = value == "1";
    else if (key == "--print") {
      fmt::print("{}", limber::fuzz::generate_mechanism_case(std::stoull(value)));
      std::exit(0);
    }
    else {
      fmt::print(stderr, "fuzz_mechanisms: unknown option {}\n", key);
      std::exit(2);
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  fs::create_directories(options.out);

  // The watchdog: a case that has not ended in kHangSeconds is a hang.
  std::atomic<long long> case_started_ns{0};
  std::atomic<std::uint64_t> current_seed{0};
  std::thread([&] {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::seconds(1));
      const long long started = case_started_ns.load();
      if (started != 0 &&
          Clock::now().time_since_epoch().count() - started > kHangSeconds * 1'000'000'000LL) {
        fmt::print(stderr, "fuzz_mechanisms: seed {} still running after {} s: a hang (case in {})\n",
                   current_seed.load(), kHangSeconds, options.out.string());
        std::fflush(stderr);
        std::_Exit(3);
      }
    }
  }).detach();

  const auto start = Clock::now();
  std::map<std::string, int> counts;
  int cases = 0, findings = 0;
  for (std::uint64_t seed = options.first_seed;; ++seed) {
    if (options.count >= 0 && cases >= options.count) break;
    if (std::chrono::duration<double>(Clock::now() - start).count() >= options.seconds) break;
    const std::string text = limber::fuzz::generate_mechanism_case(seed);
    const fs::path file = options.out / fmt::format("seed-{}.yaml", seed);
    std::ofstream(file) << text;
    fmt::print("seed {}:", seed);
    std::fflush(stdout);
    current_seed = seed;
    case_started_ns = static_cast<long long>(Clock::now().time_since_epoch().count());

    std::string finding;
    for (const auto& [method, name] : {std::pair{limber::integrate::Method::kIda, "ida"},
                                        std::pair{limber::integrate::Method::kGeneralizedAlpha, "galpha"}}) {
      const limber::fuzz::MechanismOutcome outcome = limber::fuzz::run_mechanism_case(
          text, file.string(), method, (options.out / "results").string());
      ++counts[fmt::format("{:6} {}", name, outcome.status)];
      fmt::print(" {} {} ({:.2f} s)", name, outcome.status, outcome.wall_seconds);
      // Why a run did not finish, shortened to a line.
      if (!outcome.message.empty()) fmt::print(" [{:.400}]", outcome.message);
      if (!outcome.finding.empty()) finding += fmt::format("{}: {}; ", name, outcome.finding);
    }
    case_started_ns = 0;
    ++cases;
    if (finding.empty()) {
      fmt::print("\n");
      if (!options.keep) fs::remove(file);
    } else {
      ++findings;
      const fs::path kept = options.out / fmt::format("finding-seed-{}.yaml", seed);
      fs::rename(file, kept);
      fmt::print("\n  FINDING: {}kept as {}\n", finding, kept.string());
    }
    std::fflush(stdout);
  }

  fmt::print("\n{} mechanisms (seeds {} to {}), {} runs in {:.0f} s; {} findings\n", cases,
             options.first_seed, options.first_seed + cases - 1, 2 * cases,
             std::chrono::duration<double>(Clock::now() - start).count(), findings);
  for (const auto& [outcome, count] : counts) fmt::print("  {:5} {}\n", count, outcome);
  return findings == 0 ? 0 : 1;
}
