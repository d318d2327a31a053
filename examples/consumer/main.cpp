// A consumer of the installed certimesh library: a few exact signs that naive double
// arithmetic gets wrong. Exit status 0 when every sign is right, 1 otherwise.
// Built by CMake (CMakeLists.txt, find_package) and by pkg-config:
//   c++ -std=c++20 main.cpp $(pkg-config --cflags --libs certimesh) -o consumer
#include <certimesh/predicates/incircle.h>
#include <certimesh/predicates/orient2d.h>
#include <certimesh/predicates/orient3d.h>

#include <cmath>
#include <cstdio>

namespace cp = certimesh::predicates;

static int failures = 0;

static void expect(const char* what, cp::Sign got, int want) {
  const bool ok = cp::to_int(got) == want;
  std::printf("%-44s %+d %s\n", what, cp::to_int(got), ok ? "ok" : "WRONG");
  if (!ok) ++failures;
}

int main() {
  // Kettner et al.: (0.5, 0.5), (12, 12), (24, 24) are collinear; one ulp to the right of
  // (0.5, 0.5) the triangle turns clockwise.
  const cp::Point2 q{12, 12}, r{24, 24};
  expect("orient2d collinear diagonal", cp::orient2d({0.5, 0.5}, q, r), 0);
  expect("orient2d one ulp off the diagonal",
         cp::orient2d({std::nextafter(0.5, 1.0), 0.5}, q, r), -1);

  // The monograph's printed 2D filter bound certifies +1 here; the exact sign is -1.
  expect("orient2d printed-bound counterexample",
         cp::orient2d({182.77170981294643, 403.68866801506164},
                      {771.92835113580475, 974.08982576763151},
                      {773.53783630239855, 975.64807384296398}),
         -1);

  // The same for the printed 3D bound.
  expect("orient3d printed-bound counterexample",
         cp::orient3d({35472.868317357534, 3499.4805511462346, 48723.740481790053},
                      {23576.189596565688, -17559.419569371272, 76052.766231461836},
                      {3207.2992062130597, 44557.537132935824, 18380.254590067627},
                      {37046.662608412546, 44015.035394505234, 4960.9910725431764}),
         -1);

  // Four cocircular points: exactly zero; the centre of the unit circle: inside.
  expect("incircle cocircular", cp::incircle({1, 0}, {0, 1}, {-1, 0}, {0, -1}), 0);
  expect("incircle centre", cp::incircle({1, 0}, {0, 1}, {-1, 0}, {0, 0}), 1);

  return failures == 0 ? 0 : 1;
}
