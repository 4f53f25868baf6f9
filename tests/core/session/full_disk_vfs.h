#pragma once
// A disk that fills up, for tests: an SQLite VFS that wraps the default one
// and, once armed with a byte budget, fails every write beyond it with
// SQLITE_FULL (what the unix VFS returns for ENOSPC). Installed as the
// default VFS, so SessionWriter uses it without knowing.

#include <sqlite3.h>

#include <atomic>
#include <cstring>

namespace fog::test {

class FullDiskVfs {
 public:
  // Installs the VFS once (idempotent); unarmed it only forwards.
  static void install() {
    static const bool done = [] {
      real_ = sqlite3_vfs_find(nullptr);
      vfs_ = *real_;
      vfs_.pNext = nullptr;
      vfs_.zName = "fog-full-disk";
      vfs_.szOsFile = static_cast<int>(sizeof(File)) + real_->szOsFile;
      vfs_.xOpen = &open;
      sqlite3_vfs_register(&vfs_, 1);
      return true;
    }();
    (void)done;
  }
  // Writes of more than `bytes` in total (from now on) fail.
  static void arm(long long bytes) { budget_ = bytes; }
  static void disarm() { budget_ = -1; }
  static long long refusedWrites() { return refused_; }

 private:
  struct File {
    sqlite3_file base;
    sqlite3_file* real;
  };
  static sqlite3_file* inner(sqlite3_file* f) { return reinterpret_cast<File*>(f)->real; }

  static int open(sqlite3_vfs*, sqlite3_filename name, sqlite3_file* file, int flags, int* outFlags) {
    auto* f = reinterpret_cast<File*>(file);
    f->real = reinterpret_cast<sqlite3_file*>(f + 1);
    const int rc = real_->xOpen(real_, name, f->real, flags, outFlags);
    f->base.pMethods = f->real->pMethods ? &methods_ : nullptr;
    return rc;
  }
  static int write(sqlite3_file* f, const void* data, int amount, sqlite3_int64 offset) {
    for (long long left = budget_.load(); left >= 0;) {
      if (left < amount) {
        budget_ = 0;
        ++refused_;
        return SQLITE_FULL;
      }
      if (budget_.compare_exchange_weak(left, left - amount)) break;
    }
    return inner(f)->pMethods->xWrite(inner(f), data, amount, offset);
  }
  static int truncate(sqlite3_file* f, sqlite3_int64 size) { return inner(f)->pMethods->xTruncate(inner(f), size); }
  static int close(sqlite3_file* f) { return inner(f)->pMethods->xClose(inner(f)); }
  static int read(sqlite3_file* f, void* data, int amount, sqlite3_int64 offset) {
    return inner(f)->pMethods->xRead(inner(f), data, amount, offset);
  }
  static int sync(sqlite3_file* f, int flags) { return inner(f)->pMethods->xSync(inner(f), flags); }
  static int fileSize(sqlite3_file* f, sqlite3_int64* size) { return inner(f)->pMethods->xFileSize(inner(f), size); }
  static int lock(sqlite3_file* f, int l) { return inner(f)->pMethods->xLock(inner(f), l); }
  static int unlock(sqlite3_file* f, int l) { return inner(f)->pMethods->xUnlock(inner(f), l); }
  static int checkReserved(sqlite3_file* f, int* out) { return inner(f)->pMethods->xCheckReservedLock(inner(f), out); }
  static int fileControl(sqlite3_file* f, int op, void* arg) { return inner(f)->pMethods->xFileControl(inner(f), op, arg); }
  static int sectorSize(sqlite3_file* f) { return inner(f)->pMethods->xSectorSize(inner(f)); }
  static int deviceCharacteristics(sqlite3_file* f) { return inner(f)->pMethods->xDeviceCharacteristics(inner(f)); }
  static int shmMap(sqlite3_file* f, int region, int size, int extend, void volatile** out) {
    return inner(f)->pMethods->xShmMap(inner(f), region, size, extend, out);
  }
  static int shmLock(sqlite3_file* f, int offset, int n, int flags) {
    return inner(f)->pMethods->xShmLock(inner(f), offset, n, flags);
  }
  static void shmBarrier(sqlite3_file* f) { inner(f)->pMethods->xShmBarrier(inner(f)); }
  static int shmUnmap(sqlite3_file* f, int deleteFlag) { return inner(f)->pMethods->xShmUnmap(inner(f), deleteFlag); }

  static inline sqlite3_vfs* real_ = nullptr;
  static inline sqlite3_vfs vfs_{};
  static inline std::atomic<long long> budget_{-1};
  static inline std::atomic<long long> refused_{0};
  static inline const sqlite3_io_methods methods_ = {
      2,        &close,      &read,       &write,         &truncate,        &sync,     &fileSize,
      &lock,    &unlock,     &checkReserved, &fileControl, &sectorSize,     &deviceCharacteristics,
      &shmMap,  &shmLock,    &shmBarrier, &shmUnmap,
      nullptr,  nullptr};
};

}  // namespace fog::test
