#pragma once
// formatNumber: the shortest decimal text that reads back as the same double ("3", "0.1",
// "1e+300", "nan", "inf"). Error messages quote user values with it, so "got l=3 > m=2"
// shows the numbers as the user wrote them, and values that differ only in late digits still
// print differently.
#include <string>

namespace fsdb {

std::string formatNumber(double x);

}  // namespace fsdb
