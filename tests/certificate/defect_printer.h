// GoogleTest prints a Defect by its name (found by argument-dependent lookup), so that a
// failed EXPECT_EQ on defects reads "inverted_element", not "4-byte object <0a-00 00-00>".
#pragma once

#include <ostream>

#include "certimesh/certificate/defect.h"

namespace certimesh::certificate {

inline void PrintTo(Defect defect, std::ostream* os) { *os << defect_name(defect); }

}  // namespace certimesh::certificate
