#pragma once
// The serial baud rates a Linux driver takes by name (1200 .. 4000000), for
// every serial link of the bench: the sampling board (core/serial) and a
// turntable controller on a serial line (core/table).

#include <string>
#include <termios.h>

namespace fog {

// The termios code of `baud`; B0 when the driver has no name for it.
speed_t baudRateCode(int baud);
// "1200, 2400, ..., 4000000": what a refusal lists.
std::string acceptedBaudRates();

}  // namespace fog
