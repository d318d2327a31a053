#include "certimesh/fuzz/campaign/campaign.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "certimesh/fuzz/campaign/case_seed.h"

namespace certimesh::fuzz::campaign {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();

std::optional<Finding> run_guarded(const Target& target, std::uint64_t seed) {
  try {
    return target.run_case(seed);
  } catch (const std::exception& e) {
    return Finding{std::string("exception: ") + e.what(), ""};
  } catch (...) {
    return Finding{"exception: (not a std::exception)", ""};
  }
}

// What the workers share. `lowest` is the lowest failing index found so far: without
// keep_going no worker runs an index at or above it, and every index below it that any
// chunk covers is run, so the final `lowest` does not depend on the scheduling.
struct Shared {
  Shared(const Target& t, const CampaignOptions& o, std::uint64_t l) : target(t), options(o), limit(l) {}
  const Target& target;
  const CampaignOptions& options;
  std::uint64_t limit;  // one past the last index the cases budget allows
  std::atomic<std::uint64_t> next_chunk{0};
  std::atomic<std::uint64_t> lowest{kNone};
  std::atomic<std::uint64_t> cases_run{0};
  std::atomic<bool> out_of_time{false};
  std::mutex findings_mutex;
  std::vector<CaseFinding> findings;

  void record(CaseFinding f) {
    std::uint64_t seen = lowest.load();
    while (f.case_index < seen && !lowest.compare_exchange_weak(seen, f.case_index)) {
    }
    std::lock_guard lock(findings_mutex);
    findings.push_back(std::move(f));
    std::sort(findings.begin(), findings.end(),
              [](const CaseFinding& a, const CaseFinding& b) { return a.case_index < b.case_index; });
    if (findings.size() > options.max_findings) findings.resize(options.max_findings);
  }

  void work() {
    const std::uint64_t chunk = options.chunk;
    for (;;) {
      if (out_of_time.load(std::memory_order_relaxed)) return;
      const std::uint64_t start = next_chunk.fetch_add(1) * chunk;
      if (start >= limit) return;
      if (!options.keep_going && start >= lowest.load()) return;
      const std::uint64_t end = std::min(limit, start + chunk);
      std::uint64_t ran = 0;
      for (std::uint64_t i = start; i < end; ++i) {
        if (!options.keep_going && i >= lowest.load(std::memory_order_relaxed)) break;
        const std::uint64_t seed = case_seed(options.seed, i);
        ++ran;
        if (auto f = run_guarded(target, seed)) record({i, seed, std::move(*f)});
      }
      cases_run.fetch_add(ran, std::memory_order_relaxed);
    }
  }
};

}  // namespace

CampaignResult run_campaign(const Target& target, const CampaignOptions& options,
                            const ProgressCallback& progress) {
  if (options.cases == 0 && !(options.seconds > 0.0))
    throw std::invalid_argument("run_campaign: neither a cases nor a seconds budget");
  if (options.jobs == 0) throw std::invalid_argument("run_campaign: jobs must be at least 1");
  if (options.chunk == 0) throw std::invalid_argument("run_campaign: chunk must be at least 1");
  if (!(options.progress_interval > 0.0)) throw std::invalid_argument("run_campaign: progress_interval must be positive");
  Shared shared(target, options, options.cases > 0 ? options.cases : kNone);

  const auto start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  std::mutex done_mutex;
  std::condition_variable done_cv;
  unsigned running = options.jobs;
  std::vector<std::thread> workers;
  workers.reserve(options.jobs);
  for (unsigned j = 0; j < options.jobs; ++j)
    workers.emplace_back([&] {
      shared.work();
      std::lock_guard lock(done_mutex);
      --running;
      done_cv.notify_all();
    });

  // The calling thread keeps the clock and reports progress. It sleeps until the next
  // report or the deadline, whichever comes first, or until the last worker is done.
  double next_report = options.progress_interval;
  bool deadline_passed = false;
  for (;;) {
    double wake = next_report;
    if (options.seconds > 0.0 && !deadline_passed) wake = std::min(wake, options.seconds);
    {
      std::unique_lock lock(done_mutex);
      const double now = elapsed();
      if (running > 0 && wake > now)
        done_cv.wait_for(lock, std::chrono::duration<double>(wake - now), [&] { return running == 0; });
      if (running == 0) break;
    }
    const double t = elapsed();
    if (options.seconds > 0.0 && t >= options.seconds && !deadline_passed) {
      deadline_passed = true;
      shared.out_of_time.store(true);
    }
    if (t >= next_report) {
      if (progress) {
        std::uint64_t found = 0;
        {
          std::lock_guard f(shared.findings_mutex);
          found = shared.findings.size();
        }
        progress({shared.cases_run.load(), t, found});
      }
      next_report = t + options.progress_interval;
    }
  }
  for (auto& w : workers) w.join();

  CampaignResult result;
  result.seconds = elapsed();
  result.cases_run = shared.cases_run.load();
  result.cases_per_second = result.seconds > 0.0 ? static_cast<double>(result.cases_run) / result.seconds : 0.0;
  result.findings = std::move(shared.findings);
  if (!options.keep_going && result.findings.size() > 1) result.findings.resize(1);
  return result;
}

}  // namespace certimesh::fuzz::campaign
