// The certimesh command-line tool: subcommand entry points. The library never prints;
// everything the user sees is rendered here.
#pragma once

#include <string>

namespace certimesh::cli {

enum class BatchMode { exact, filter, sos };

struct BatchOptions {
  BatchMode mode = BatchMode::exact;
  bool line_buffered = false;  // flush stdout after every answer (for co-processes)
};

/// `certimesh predicates`: reads predicate queries from stdin, one per line, and writes one
/// answer per query line to stdout. Returns 0 when every line was answered, 1 when at least
/// one line was rejected (each rejection is reported on stderr as `error: line N: why`).
int run_batch(const BatchOptions& options);

/// `certimesh convert IN OUT`: reads IN and writes OUT, formats chosen by extension.
/// Returns 0 on success, 2 when IN is unreadable or OUT cannot be written (`error: ...`).
int run_convert(const std::string& input, const std::string& output);

struct CheckOptions {
  std::string mesh;
  std::string domain;       // empty: no domain
  std::string certificate;  // empty: no JSON certificate written
};

/// `certimesh check MESH [--domain D] [--certificate OUT.json]`: the independent certificate.
/// Returns 0 valid, 1 invalid (first offending element or facet named), 2 unreadable input.
int run_check(const CheckOptions& options);

/// `certimesh demo`: the classroom failures of naive floating point, and certimesh's answers.
int run_demo();

}  // namespace certimesh::cli
