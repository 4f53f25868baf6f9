#pragma once
// One way to spread independent jobs over the machine's cores, for the
// diagnosis, its blind check and the accuracy study.

#include <cstddef>
#include <functional>

namespace fog {

// Runs job(i) once for every i in [0, n) on up to `threads` threads (the
// calling thread is one of them) and returns when all are done. Jobs for
// distinct i run concurrently: each must write only its own slot.
void parallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& job);

}  // namespace fog
