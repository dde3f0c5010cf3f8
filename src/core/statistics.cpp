#include "core/statistics.h"

#include <algorithm>
#include <stdexcept>

namespace fp {

double median(std::vector<double> values) {
    if (values.empty()) throw std::invalid_argument("median of no values");
    size_t n = values.size(), middle = n / 2;
    std::nth_element(values.begin(), values.begin() + middle, values.end());
    double upper = values[middle];
    if (n % 2) return upper;
    double lower = *std::max_element(values.begin(), values.begin() + middle);
    return 0.5 * (lower + upper);
}

}  // namespace fp
