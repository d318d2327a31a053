// RapidCheck generators over the recipes of recipes.h.
//
// Include <gtest/gtest.h> before <rapidcheck/gtest.h> in test files (doc/gtest.md); this
// header needs only <rapidcheck.h>.
//
// Every recipe draw is a `*gen::inRange` pick inside gen::exec, so each parameter shrinks
// on its own (towards its lower bound). The near-degenerate `nextafter` family is
// gen::mapcat(exact base, perturbation): RapidCheck shrinks the base first -- every base it
// tries is still exactly degenerate, because the constructions are exact for all
// parameters -- and then the ulp steps.
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <iomanip>
#include <limits>
#include <ostream>
#include <type_traits>

#include "certimesh/fuzz/recipes.h"

namespace certimesh::fuzz {

/// Prints a configuration with hex floats (exact and reproducible).
template <std::size_t N, std::size_t Dim>
void showValue(const Config<N, Dim>& c, std::ostream& os) {
  os << "{" << c.family << ", " << kind_name(c.kind) << ", " << binade_name(c.binade) << ":";
  for (const auto& pt : c.p) {
    os << " (";
    for (std::size_t k = 0; k < Dim; ++k) os << (k ? ", " : "") << std::hexfloat << pt[k];
    os << ")";
  }
  os << std::defaultfloat << "}";
}

namespace rcgen {

/// RapidCheck's size parameter at which gen::inRange covers its whole range.
inline constexpr int kFullSize = 100;

/// A uniform pick in [lo, hi) whatever the current size: gen::inRange scales its range by
/// the size (at size 0 it always returns lo), which would make the first cases of every
/// run trivial. Shrinks towards lo.
template <class T>
T pick(T lo, T hi) {
  return *rc::gen::resize(kFullSize, rc::gen::inRange<T>(lo, hi));
}

/// A draw source whose draws are shrinkable RapidCheck picks (use inside gen::exec).
struct RcDraw {
  std::uint64_t below(std::uint64_t n) { return n <= 1 ? 0 : pick<std::uint64_t>(0, n); }
  std::uint64_t bits() { return pick<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()); }
};

template <class F>
rc::Gen<std::invoke_result_t<F, RcDraw&>> recipe(F f) {
  return rc::gen::resize(kFullSize, rc::gen::exec([f] {
                           RcDraw d;
                           return f(d);
                         }));
}

template <class Cfg, class ExactF, class RoundedF>
rc::Gen<Cfg> near_of(ExactF exact, RoundedF rounded) {
  auto base = recipe(exact);
  auto perturbed = rc::gen::mapcat(base, [](Cfg b) {
    return recipe([b](RcDraw& d) { return nextafter_perturbation(b, d); });
  });
  return rc::gen::resize(kFullSize,
                         rc::gen::weightedOneOf<Cfg>({{1, perturbed}, {1, recipe(rounded)}}));
}

template <class Cfg>
rc::Gen<Cfg> mixture(rc::Gen<Cfg> exact, rc::Gen<Cfg> near, rc::Gen<Cfg> generic) {
  return rc::gen::resize(kFullSize,
                         rc::gen::weightedOneOf<Cfg>({{4, exact}, {4, near}, {2, generic}}));
}

// Exactly degenerate configurations only.
inline rc::Gen<Orient2dInput> exact_orient2d() { return recipe([](RcDraw& d) { return fuzz::exact_orient2d(d); }); }
inline rc::Gen<Orient3dInput> exact_orient3d() { return recipe([](RcDraw& d) { return fuzz::exact_orient3d(d); }); }
inline rc::Gen<IncircleInput> exact_incircle() { return recipe([](RcDraw& d) { return fuzz::exact_incircle(d); }); }
inline rc::Gen<InsphereInput> exact_insphere() { return recipe([](RcDraw& d) { return fuzz::exact_insphere(d); }); }

// Near-degenerate configurations only.
inline rc::Gen<Orient2dInput> near_orient2d() {
  return near_of<Orient2dInput>([](RcDraw& d) { return fuzz::exact_orient2d(d); },
                     [](RcDraw& d) { return fuzz::rounded_orient2d(d); });
}
inline rc::Gen<Orient3dInput> near_orient3d() {
  return near_of<Orient3dInput>([](RcDraw& d) { return fuzz::exact_orient3d(d); },
                     [](RcDraw& d) { return fuzz::rounded_orient3d(d); });
}
inline rc::Gen<IncircleInput> near_incircle() {
  return near_of<IncircleInput>([](RcDraw& d) { return fuzz::exact_incircle(d); },
                     [](RcDraw& d) { return fuzz::rounded_incircle(d); });
}
inline rc::Gen<InsphereInput> near_insphere() {
  return near_of<InsphereInput>([](RcDraw& d) { return fuzz::exact_insphere(d); },
                     [](RcDraw& d) { return fuzz::rounded_insphere(d); });
}

// Generic configurations (bit patterns by class, exponent-mixed scales).
template <std::size_t N, std::size_t Dim>
rc::Gen<Config<N, Dim>> generic() {
  return recipe([](RcDraw& d) { return generic_config<N, Dim>(d); });
}

// The full mixture per predicate: 40 % exactly degenerate, 40 % near, 20 % generic.
inline rc::Gen<Orient2dInput> orient2d_input() { return mixture(exact_orient2d(), near_orient2d(), generic<3, 2>()); }
inline rc::Gen<Orient3dInput> orient3d_input() { return mixture(exact_orient3d(), near_orient3d(), generic<4, 3>()); }
inline rc::Gen<IncircleInput> incircle_input() { return mixture(exact_incircle(), near_incircle(), generic<4, 2>()); }
inline rc::Gen<InsphereInput> insphere_input() { return mixture(exact_insphere(), near_insphere(), generic<5, 3>()); }

/// A double of one class, from its bit pattern.
inline rc::Gen<double> double_of_class(DoubleClass c) {
  return recipe([c](RcDraw& d) { return draw_double(d, c); });
}

}  // namespace rcgen
}  // namespace certimesh::fuzz
