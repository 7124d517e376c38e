// Linked into the Linux libraries for Abaqus (libexplicitU.so,
// libexplicitU-D.so, libstandardU.so) so that they load on the oldest glibc
// the Abaqus releases run on (2.28; docs/abaqus.md, "Which Linux"):
//
//  - exp, log and hypot are called through their oldest symbol versions
//    (GLIBC_2.2.5). Newer versions of the same functions exist only to drop
//    the SVID error-handling wrapper; on a given glibc both versions return
//    the same value for every argument the law passes (finite, no overflow).
//    The libraries are linked with --wrap=exp,log,hypot, so every call the
//    law makes lands here.
//  - The static C++ runtime asks glibc whether the process is single-threaded
//    (__libc_single_threaded, a variable of newer glibc). Defined here, local
//    to the library, as "not known to be": the runtime always takes its
//    thread-safe path (atomic reference counts, locked static
//    initialisation), which is right in any process.
//
// tests/abi/check_linux_library.cmake checks the result with objdump -T.
extern "C" {

__attribute__((visibility("hidden"))) char __libc_single_threaded = 0;

double mj_exp_glibc_2_2_5(double);
double mj_log_glibc_2_2_5(double);
double mj_hypot_glibc_2_2_5(double, double);
__asm__(".symver mj_exp_glibc_2_2_5, exp@GLIBC_2.2.5");
__asm__(".symver mj_log_glibc_2_2_5, log@GLIBC_2.2.5");
__asm__(".symver mj_hypot_glibc_2_2_5, hypot@GLIBC_2.2.5");

__attribute__((visibility("hidden"))) double __wrap_exp(double x) { return mj_exp_glibc_2_2_5(x); }
__attribute__((visibility("hidden"))) double __wrap_log(double x) { return mj_log_glibc_2_2_5(x); }
__attribute__((visibility("hidden"))) double __wrap_hypot(double x, double y) { return mj_hypot_glibc_2_2_5(x, y); }

}  // extern "C"
