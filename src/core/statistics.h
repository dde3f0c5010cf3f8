#pragma once
// Summaries of repeated measurements.
#include <vector>

namespace fp {

// The middle value (the mean of the two middle ones for an even count), so that one outlier, such as a
// run disturbed by another process, does not move it. Throws std::invalid_argument for no values: asking
// for the median of nothing is a bug.
double median(std::vector<double> values);

}  // namespace fp
