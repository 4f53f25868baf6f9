#include "core/common/baud_rates.h"

namespace fog {
namespace {

struct Rate {
  int baud;
  speed_t code;
};
constexpr Rate kRates[] = {{1200, B1200},       {2400, B2400},       {4800, B4800},       {9600, B9600},
                           {19200, B19200},     {38400, B38400},     {57600, B57600},     {115200, B115200},
                           {230400, B230400},   {460800, B460800},   {500000, B500000},   {576000, B576000},
                           {921600, B921600},   {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
                           {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000},
                           {4000000, B4000000}};

}  // namespace

speed_t baudRateCode(int baud) {
  for (const Rate& r : kRates)
    if (r.baud == baud) return r.code;
  return B0;
}

std::string acceptedBaudRates() {
  std::string s;
  for (const Rate& r : kRates) s += (s.empty() ? "" : ", ") + std::to_string(r.baud);
  return s;
}

}  // namespace fog
