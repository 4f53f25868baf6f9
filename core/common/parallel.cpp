#include "core/common/parallel.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace fog {

void parallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& job) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) job(i);
  };
  const int t = std::max(1, std::min<int>(threads, static_cast<int>(std::min<std::size_t>(n, 1024))));
  std::vector<std::thread> pool;
  for (int k = 1; k < t; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
}

}  // namespace fog
