// A campaign target: one property of certimesh, checked case by case against an oracle that
// shares no code with what it tests. A case is a 64-bit seed; a finding carries a payload,
// the case's input as text, so that a reproducer file replays it without the generators
// (which may change) and the seed replays it with them.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace certimesh::fuzz::campaign {

/// A violated property: what failed, and the input that makes it fail.
struct Finding {
  std::string message;  // one line: "orient2d: the filter contradicts the rational oracle"
  std::string payload;  // one line: the input, doubles as C99 hex floats (%a)
  friend bool operator==(const Finding&, const Finding&) = default;
};

/// A payload that replay() cannot read (a hand-edited or foreign reproducer).
class MalformedPayload : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Target {
 public:
  virtual ~Target() = default;
  /// The name `certimesh fuzz NAME` selects.
  virtual std::string_view name() const = 0;
  /// One line on what it checks, against what (`certimesh fuzz --list`).
  virtual std::string_view description() const = 0;
  /// Draws case `seed`'s input and checks it. Called from several threads at once: no
  /// shared mutable state.
  virtual std::optional<Finding> run_case(std::uint64_t seed) const = 0;
  /// Checks the input a Finding's payload names. Throws MalformedPayload.
  virtual std::optional<Finding> replay(std::string_view payload) const = 0;
};

/// The targets a program knows. The shipped CLI fills it with builtin_targets(); a test
/// executable may add its own (mutants), which therefore never reach the CLI.
class TargetRegistry {
 public:
  /// Throws std::invalid_argument when a target of that name is already registered.
  void add(std::unique_ptr<Target> target);
  /// nullptr when no target has that name.
  const Target* find(std::string_view name) const;
  /// In registration order.
  std::vector<const Target*> all() const;

 private:
  std::vector<std::unique_ptr<Target>> targets_;
};

/// The targets `certimesh fuzz` ships: predicates, intersection, readers, delaunay2d, mesh2d.
TargetRegistry builtin_targets();

}  // namespace certimesh::fuzz::campaign
