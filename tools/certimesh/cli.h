// The certimesh command-line tool: subcommand entry points. The library never prints;
// everything the user sees is rendered here.
#pragma once

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

/// `certimesh demo`: the classroom failures of naive floating point, and certimesh's answers.
int run_demo();

}  // namespace certimesh::cli
