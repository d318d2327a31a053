// "The generators bite": the textbook double-precision formula of each predicate, run on
// the same generators as the property tests, must disagree with the rational oracle within
// 10^5 cases. Otherwise the generators would be too tame to test an exact kernel. Each test
// also reports the naive failure rate per kind of input over 10^4 cases.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "support.h"

namespace certimesh::test {
namespace {

template <class T>
void generators_bite() {
  // 1. The first disagreement (RapidCheck shrinks it to a small counterexample).
  const std::string id = std::string(T::name) + ".naive_double_fails";
  const auto result = run_property(
      id, 100000,
      [] {
        const auto c = *T::gen();
        RC_ASSERT(T::naive(c.p) == T::oracle(c.p));
      },
      /*expect_success=*/false);
  ASSERT_TRUE(result.template is<rc::detail::FailureResult>())
      << T::name << ": naive double survived 10^5 generated cases";
  const auto& failure = result.template get<rc::detail::FailureResult>();
  std::cout << "[generators bite " << T::name << "] naive double first wrong at case "
            << failure.numSuccess + 1 << "; shrunk counterexample:\n";
  rc::detail::printResultMessage(result, std::cout);
  std::cout << std::endl;
  EXPECT_LT(failure.numSuccess, 100000);

  // 2. The naive failure rate per kind of input.
  const std::string rate_id = std::string(T::name) + ".naive_double_failure_rate";
  const auto rates = run_property(rate_id, 10000, [] {
    const auto c = *T::gen();
    const int o = T::oracle(c.p);
    const int n = T::naive(c.p);
    const char* kind = o == 0 ? "exactly-degenerate"
                              : (c.kind == fz::Kind::near_degenerate ? "near-degenerate" : "generic");
    RC_TAG(kind, n == o ? "naive-right" : "naive-wrong");
  });
  ASSERT_TRUE(rates.template is<rc::detail::SuccessResult>());
  EXPECT_GT(tag_share(rates.template get<rc::detail::SuccessResult>().distribution, "naive-wrong"), 0.0);
}

TEST(GeneratorsBite, Orient2dNaiveDoubleFails) { generators_bite<Orient2d>(); }
TEST(GeneratorsBite, Orient3dNaiveDoubleFails) { generators_bite<Orient3d>(); }
TEST(GeneratorsBite, IncircleNaiveDoubleFails) { generators_bite<Incircle>(); }
TEST(GeneratorsBite, InsphereNaiveDoubleFails) { generators_bite<Insphere>(); }

}  // namespace
}  // namespace certimesh::test
