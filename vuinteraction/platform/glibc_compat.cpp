// Linked into the Linux libraries for Abaqus so that they load on the oldest
// glibc the Abaqus releases run on (docs/abaqus.md, "Which Linux"): exp,
// log and hypot through their oldest symbol versions (--wrap=exp,log,hypot:
// every call of the law lands here; the values are the same), and
// __libc_single_threaded defined as "not known to be", so that the static
// C++ runtime always takes its thread-safe path.
// tests/abi/check_linux_library.cmake checks the result with objdump -T.
// The rest: docs/adapters.md, section 10.
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
