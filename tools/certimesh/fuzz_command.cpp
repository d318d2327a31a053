// `certimesh fuzz`: runs a campaign target (fuzz/campaign) for a budget, prints progress on
// stderr and a summary on stdout, writes a reproducer per finding and optionally a JSON
// report; `--list` names the targets, `--replay FILE` re-runs one reproducer.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "certimesh/fuzz/campaign/campaign.h"
#include "certimesh/fuzz/campaign/reproducer.h"
#include "certimesh/fuzz/campaign/target.h"
#include "certimesh_commit.h"  // CERTIMESH_COMMIT, generated at build time
#include "cli.h"

namespace certimesh::cli {

namespace {

namespace fc = certimesh::fuzz::campaign;

int usage(const std::string& why) {
  std::fprintf(stderr, "error: fuzz: %s (see certimesh fuzz --help)\n", why.c_str());
  return 2;
}

std::string hex(std::uint64_t v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "0x%llx", static_cast<unsigned long long>(v));
  return buffer;
}

void json_string(std::string& out, std::string_view text) {
  out += '"';
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
      out += esc;
    } else {
      out += c;
    }
  }
  out += '"';
}

std::string json_report(const FuzzOptions& o, const fc::CampaignResult& r,
                        const std::vector<std::string>& reproducers) {
  char number[64];
  std::string out = "{\n  \"target\": ";
  json_string(out, o.target);
  out += ",\n  \"commit\": ";
  json_string(out, CERTIMESH_COMMIT);
  out += ",\n  \"seed\": ";
  json_string(out, hex(o.seed));
  out += ",\n  \"jobs\": " + std::to_string(o.jobs);
  out += ",\n  \"cases\": " + std::to_string(r.cases_run);
  std::snprintf(number, sizeof number, "%.3f", r.seconds);
  out += ",\n  \"seconds\": " + std::string(number);
  std::snprintf(number, sizeof number, "%.0f", r.cases_per_second);
  out += ",\n  \"cases_per_second\": " + std::string(number);
  out += ",\n  \"findings\": [";
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    const auto& f = r.findings[i];
    out += i ? ",\n    {" : "\n    {";
    out += "\"case\": " + std::to_string(f.case_index) + ", \"case_seed\": ";
    json_string(out, hex(f.case_seed));
    out += ", \"message\": ";
    json_string(out, f.finding.message);
    out += ", \"payload\": ";
    json_string(out, f.finding.payload);
    out += ", \"reproducer\": ";
    json_string(out, i < reproducers.size() ? reproducers[i] : "");
    out += "}";
  }
  out += r.findings.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  return static_cast<bool>(out);
}

int list_targets(const fc::TargetRegistry& registry) {
  for (const fc::Target* t : registry.all())
    std::printf("%-14s %s\n", std::string(t->name()).c_str(), std::string(t->description()).c_str());
  return 0;
}

int replay(const fc::TargetRegistry& registry, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::fprintf(stderr, "error: %s: cannot read the reproducer\n", path.c_str()), 2;
  std::stringstream text;
  text << in.rdbuf();
  fc::Reproducer r;
  try {
    r = fc::parse_reproducer(text.str());
  } catch (const fc::MalformedReproducer& e) {
    return std::fprintf(stderr, "error: %s: %s\n", path.c_str(), e.what()), 2;
  }
  const fc::Target* target = registry.find(r.target);
  if (!target) return std::fprintf(stderr, "error: %s: unknown target '%s' (certimesh fuzz --list)\n", path.c_str(), r.target.c_str()), 2;
  std::optional<fc::Finding> now;
  try {
    now = target->replay(r.payload);
  } catch (const fc::MalformedPayload& e) {
    return std::fprintf(stderr, "error: %s: payload: %s\n", path.c_str(), e.what()), 2;
  }
  std::printf("replay %s: target %s, case %llu of seed %s\n", path.c_str(), r.target.c_str(),
              static_cast<unsigned long long>(r.case_index), hex(r.seed).c_str());
  std::printf("  recorded: %s\n", r.message.c_str());
  std::printf("  now:      %s\n", now ? now->message.c_str() : "no finding (fixed?)");
  // The seed re-derives the case through the generators of this build.
  std::optional<fc::Finding> again;
  try {
    again = target->run_case(r.case_seed);
  } catch (const std::exception& e) {
    again = fc::Finding{std::string("exception: ") + e.what(), ""};
  }
  std::printf("  case-seed %s through this build's generators: %s\n", hex(r.case_seed).c_str(),
              !again ? "no finding"
                     : (again->payload == r.payload ? "the same input" : "a different input (the generators changed)"));
  return now ? 1 : 0;
}

}  // namespace

int run_fuzz(const FuzzOptions& o) {
  const fc::TargetRegistry registry = fc::builtin_targets();
  if (o.list) return list_targets(registry);
  if (!o.replay.empty()) return replay(registry, o.replay);
  const fc::Target* target = registry.find(o.target);
  if (!target) return usage("unknown target '" + o.target + "' (certimesh fuzz --list)");
  std::error_code ec;
  if (!std::filesystem::is_directory(o.out, ec)) return usage("--out '" + o.out + "' is not a directory");

  fc::CampaignOptions c;
  c.cases = o.cases;
  c.seconds = o.cases > 0 ? 0.0 : o.seconds;
  c.seed = o.seed;
  c.jobs = o.jobs;
  c.keep_going = o.keep_going;
  c.progress_interval = o.progress_interval;
  char seconds_text[32];
  std::snprintf(seconds_text, sizeof seconds_text, "%g s", c.seconds);
  const std::string budget_text = o.cases > 0 ? std::to_string(o.cases) + " cases" : std::string(seconds_text);
  std::fprintf(stderr, "fuzz %s: seed %s, %u job%s, budget %s\n", o.target.c_str(), hex(o.seed).c_str(), o.jobs,
               o.jobs == 1 ? "" : "s",
               budget_text.c_str());
  const fc::CampaignResult r = fc::run_campaign(*target, c, [&](const fc::CampaignProgress& p) {
    std::fprintf(stderr, "fuzz %s: %llu cases, %.0f s, %.0f cases/s, %llu finding%s\n", o.target.c_str(),
                 static_cast<unsigned long long>(p.cases_run), p.seconds,
                 p.seconds > 0 ? static_cast<double>(p.cases_run) / p.seconds : 0.0,
                 static_cast<unsigned long long>(p.findings), p.findings == 1 ? "" : "s");
  });

  int status = r.findings.empty() ? 0 : 1;
  std::vector<std::string> written;
  for (const auto& f : r.findings) {
    fc::Reproducer rep;
    rep.target = o.target;
    rep.seed = o.seed;
    rep.case_index = f.case_index;
    rep.case_seed = f.case_seed;
    rep.message = f.finding.message;
    rep.payload = f.finding.payload;
    const std::string path =
        (std::filesystem::path(o.out) / (o.target + "-seed" + hex(o.seed) + "-case" + std::to_string(f.case_index) + ".repro")).string();
    if (!write_file(path, fc::write_reproducer(rep))) {
      std::fprintf(stderr, "error: %s: cannot write the reproducer\n", path.c_str());
      status = 2;
    }
    written.push_back(path);
    std::printf("finding at case %llu: %s\n  payload %s\n  reproducer %s\n", static_cast<unsigned long long>(f.case_index),
                f.finding.message.c_str(), f.finding.payload.c_str(), path.c_str());
  }
  std::printf("fuzz %s: %llu cases in %.2f s, %.0f cases/s, seed %s, %u job%s: %s\n", o.target.c_str(),
              static_cast<unsigned long long>(r.cases_run), r.seconds, r.cases_per_second, hex(o.seed).c_str(), o.jobs,
              o.jobs == 1 ? "" : "s",
              r.findings.empty() ? "no finding" : (std::to_string(r.findings.size()) + " finding" + (r.findings.size() == 1 ? "" : "s")).c_str());
  if (!o.report.empty() && !write_file(o.report, json_report(o, r, written))) {
    std::fprintf(stderr, "error: %s: cannot write the report\n", o.report.c_str());
    status = 2;
  }
  return status;
}

namespace {

// A whole non-negative number (decimal, or 0x hex), or false.
bool whole_number(const char* text, std::uint64_t& out) {
  if (*text == '-' || *text == '\0') return false;
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text, &end, 0);
  if (errno != 0 || *end != '\0') return false;
  out = v;
  return true;
}

}  // namespace

int parse_and_run_fuzz(int argc, char** argv) {
  FuzzOptions o;
  bool have_seconds = false, have_cases = false;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--list") {
      o.list = true;
    } else if (arg == "--replay" && has_value) {
      o.replay = argv[++i];
    } else if (arg == "--seconds" && has_value) {
      char* end = nullptr;
      const double s = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !(s > 0.0) || !std::isfinite(s)) return usage("--seconds needs a positive number, got '" + std::string(argv[i]) + "'");
      o.seconds = s;
      have_seconds = true;
    } else if (arg == "--cases" && has_value) {
      if (!whole_number(argv[++i], o.cases) || o.cases == 0) return usage("--cases needs a whole number >= 1, got '" + std::string(argv[i]) + "'");
      have_cases = true;
    } else if (arg == "--seed" && has_value) {
      if (!whole_number(argv[++i], o.seed)) return usage("--seed needs a 64-bit whole number (decimal or 0x hex), got '" + std::string(argv[i]) + "'");
    } else if (arg == "--jobs" && has_value) {
      std::uint64_t j = 0;
      if (!whole_number(argv[++i], j) || j == 0 || j > 1024) return usage("--jobs needs a whole number in [1, 1024], got '" + std::string(argv[i]) + "'");
      o.jobs = static_cast<unsigned>(j);
    } else if (arg == "--keep-going") {
      o.keep_going = true;
    } else if (arg == "--report" && has_value) {
      o.report = argv[++i];
    } else if (arg == "--out" && has_value) {
      o.out = argv[++i];
    } else if (!arg.starts_with("-") && o.target.empty()) {
      o.target = argv[i];
    } else {
      return usage("unexpected argument '" + std::string(arg) + "'");
    }
  }
  if (have_seconds && have_cases) return usage("--seconds and --cases exclude each other");
  const int modes = int(o.list) + int(!o.replay.empty()) + int(!o.target.empty());
  if (modes == 0) return usage("needs a TARGET, --list or --replay FILE");
  if (modes > 1) return usage("TARGET, --list and --replay FILE exclude each other");
  if (!o.target.empty()) {
    const fc::TargetRegistry registry = fc::builtin_targets();
    if (!registry.find(o.target)) return usage("unknown target '" + o.target + "' (certimesh fuzz --list)");
  }
  return run_fuzz(o);
}

}  // namespace certimesh::cli
