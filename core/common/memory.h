#pragma once
// How the process hands freed memory back to the kernel.

namespace fog {

// For a process that simulates many sessions in a row (a diagnosis replays
// its session some 50 times, each replay allocating and freeing ~20 MB):
// freed blocks below 32 MB stay in the process for the next replay instead
// of going back to the kernel, to be faulted in and zeroed again (that was
// an eighth of a diagnosis' time), and up to 128 MB of free heap is kept.
// Larger blocks (an hour's samples) are still mapped and returned. glibc
// only (mallopt); elsewhere it does nothing. Call once, early in main().
void keepFreedMemoryForReuse();

}  // namespace fog
