/* Test scaffolding, never shipped: bcryptprimitives.dll for Wine 8, which lacks it. Rust's
 * standard library calls ProcessPrng from it at start-up (for HashMap's random keys); without the
 * DLL a Rust program under Wine 8 exits at once with status 53. This one forwards to RtlGenRandom
 * (advapi32's SystemFunction036), which Wine has. Built by scripts/windows.sh beside the .exe. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) {
            return FALSE;
        }
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
