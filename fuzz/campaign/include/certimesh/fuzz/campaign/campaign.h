// Running a target for a budget: cases 0, 1, 2, ... of a seed, over `jobs` threads.
//
// Threads claim chunks of case indices from one atomic counter, and every claimed chunk is
// run to its end (or to the lowest finding so far), so the cases run always form a prefix
// 0..n-1 of the index sequence, up to the first finding. Hence the first finding -- the
// lowest index that fails -- is the same for any number of jobs; with a --cases budget
// everything is. A seconds budget stops the claiming of new chunks at the deadline.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "certimesh/fuzz/campaign/target.h"

namespace certimesh::fuzz::campaign {

struct CampaignOptions {
  std::uint64_t cases = 0;      // a budget of cases; 0: the seconds budget alone
  double seconds = 0.0;         // a budget of wall-clock seconds; 0: the cases budget alone
  std::uint64_t seed = 0;       // K: case i draws from splitmix64(K ^ splitmix64(i))
  unsigned jobs = 1;            // threads
  bool keep_going = false;      // run the whole budget, collecting every finding
  std::uint64_t max_findings = 100;  // with keep_going: keep the lowest this many
  std::uint64_t chunk = 256;    // case indices claimed at a time
  double progress_interval = 1.0;  // seconds between progress reports
};

/// A finding and the case that produced it.
struct CaseFinding {
  std::uint64_t case_index = 0;
  std::uint64_t case_seed = 0;
  Finding finding;
};

struct CampaignProgress {
  std::uint64_t cases_run = 0;
  double seconds = 0.0;
  std::uint64_t findings = 0;
};

struct CampaignResult {
  std::uint64_t cases_run = 0;
  double seconds = 0.0;
  double cases_per_second = 0.0;
  std::vector<CaseFinding> findings;  // by case index; the first is the lowest failing index
};

/// Reports from the calling thread, every `progress_interval` seconds while the campaign runs.
using ProgressCallback = std::function<void(const CampaignProgress&)>;

/// Runs `target` for the budget (at least one of cases, seconds must be set: throws
/// std::invalid_argument otherwise, or for jobs == 0, chunk == 0 or progress_interval <= 0). Stops at the first
/// finding unless keep_going. An exception escaping run_case is a finding ("exception: ...").
CampaignResult run_campaign(const Target& target, const CampaignOptions& options,
                            const ProgressCallback& progress = {});

}  // namespace certimesh::fuzz::campaign
