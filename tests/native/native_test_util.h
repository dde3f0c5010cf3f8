#pragma once
// Shared pieces of the native reference's tests.
#include "native/native_path.h"
#include "render/accumulation.h"

namespace fp::test {

// The native reference's sums as the renderer's accumulation, for the statistics of render_test_util.h.
inline Accumulation asAccumulation(const native::Result& r) {
    Accumulation a;
    a.width = r.width;
    a.height = r.height;
    a.sum = r.sum;
    a.squares = r.squares;
    a.counters.assign(r.sum.size(), glm::vec4(0.0f));
    return a;
}

}  // namespace fp::test
