/* Test-only stand-in for Windows' bcryptprimitives.dll, which Wine 8.0 lacks (every
   Windows 10 and 11 has it): Rust's standard library (1.78+) imports ProcessPrng from it,
   so a Rust program does not start under Wine 8 without it. .ci/windows builds it and
   puts it beside the executables it runs under Wine; it is never part of what users get. */
#include <windows.h>
#include <ntsecapi.h>

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len) {
    while (len > 0) {
        ULONG part = len > 0x40000000 ? 0x40000000 : (ULONG)len;
        if (!RtlGenRandom(data, part)) return FALSE;
        data += part;
        len -= part;
    }
    return TRUE;
}
