/* A stand-in for Windows' bcryptprimitives.dll, for running dformer.exe under Debian's wine 8.0
 * only (tests/release/test_windows_wine.py builds it with MinGW and puts it beside the .exe).
 * Rust's standard library (1.78 and later) takes its random seeds from ProcessPrng, exported by
 * bcryptprimitives.dll, which every Windows 10 and 11 has but wine 8.0 lacks. This forwards to
 * BCryptGenRandom with the system RNG, which wine has; ProcessPrng always returns TRUE. */
#include <windows.h>
#include <bcrypt.h>

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len) {
  while (len > 0) {
    ULONG chunk = len > 0x10000000 ? 0x10000000 : (ULONG)len;
    if (BCryptGenRandom(NULL, data, chunk, BCRYPT_USE_SYSTEM_PREFERRED_RNG) != 0) return FALSE;
    data += chunk;
    len -= chunk;
  }
  return TRUE;
}
