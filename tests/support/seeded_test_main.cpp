// The main() of every test executable: GoogleTest's, with RapidCheck's seed fixed, so that
// the suite draws the same cases on every run and every machine (a property that fails fails
// always, with the same counterexample; exploring new cases is what the fuzz campaigns are
// for). RapidCheck reads RC_PARAMS when the first property runs, after static initialisation:
// a test file that sets its own RC_PARAMS there (seed and case count) keeps it; one without a
// seed gets this one appended; the caller's RC_PARAMS with a seed wins (to reproduce a run).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  const char* given = std::getenv("RC_PARAMS");
  std::string params = given ? given : "";
  if (params.find("seed=") == std::string::npos) {
    params += params.empty() ? "seed=20261202" : " seed=20261202";
    setenv("RC_PARAMS", params.c_str(), 1);
  }
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
