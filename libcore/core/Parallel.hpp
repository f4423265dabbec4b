// When a loop is worth threads. Below a few thousand items an OpenMP region costs more than it
// saves (fork/join and barriers run at every step), and on a loaded machine a descheduled
// thread stalls every barrier; small loops run on the calling thread. Results do not depend
// on this: every parallel loop computes each item independently (docs/formulation.md).
#pragma once

#include <cstddef>

namespace hvi {

inline constexpr std::size_t kParallelMinItems = 4096;

} // namespace hvi
