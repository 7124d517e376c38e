// UINTER (Abaqus/Standard contact pairs, *SURFACE INTERACTION, USER): unpacks
// the argument list into the adapter's point (adapter/standard_point.hpp,
// where Abaqus/Standard's signs meet the law's) and runs the adapters'
// skeleton (adapter/guard.hpp). Always double precision.
//
// Errors: a bad argument or property gives a line on stderr naming the
// interaction, then Abaqus/Standard's XIT. Standalone build (MJ_STANDALONE):
// no exit utility; the code in SDV 21, outputs finite.
#include "adapter/guard.hpp"
#include "adapter/standard_point.hpp"
#include "vuinteraction.h"

#ifndef MJ_STANDALONE
// Abaqus/Standard's exit utility (Fortran: CALL XIT, no arguments).
extern "C" void xit_();
#endif

namespace {

#ifdef MJ_STANDALONE
constexpr mj_adapter::ExitUtility kExit = nullptr;
#else
constexpr mj_adapter::ExitUtility kExit = xit_;
#endif

constexpr mj_adapter::Routine kUinter = {"UINTER",
                                         {"NDIR", "NDIR is 2 (2D) or 3 (3D)", "NSTATV", "NPROPS", "DROT"},
                                         mj_adapter::kStandardDefaults,
                                         "point",
                                         kExit};

}  // namespace

extern "C" void uinter_(
    double* stress, double* ddsddr, double* /*amki*/, double* /*amski*/, double* flux, double* ddfddt,
    double* ddsddt, double* ddfddr, double* statev, double* sed, double* sfd, double* spd, double* svd,
    double* scd, double* pnewdt, const double* rdisp, const double* drdisp, const double* /*temp*/,
    const double* /*dtemp*/, const double* /*predef*/, const double* /*dpred*/, const double* /*time*/,
    const double* /*dtime*/, const double* /*freqr*/, const char* ciname, const char* /*slname*/,
    const char* /*msname*/, const double* props, const double* /*coords*/, const double* /*alocaldir*/,
    const double* drot, const double* /*area*/, const double* /*chrlngth*/, const int* node, const int* ndir,
    const int* nstatv, const int* /*npred*/, const int* nprops, const int* /*mcrd*/, const int* /*kstep*/,
    const int* /*kinc*/, const int* /*kit*/, const int* linper, int* /*lopenclose*/, int* /*lstate*/,
    int* /*lsdi*/, const int* /*lprint*/, int lenCiname, int /*lenSlname*/, int /*lenMsname*/) {
  mj_adapter::StandardPoint c;
  c.counts = {*ndir, 1, *nstatv, *nprops};
  c.node = *node;
  c.perturbation = *linper == 1;
  c.rdisp = rdisp;
  c.drdisp = drdisp;
  c.drot = drot;
  c.props = props;
  c.stress = stress;
  c.ddsddr = ddsddr;
  c.statev = statev;
  c.flux = flux;
  c.ddfddt = ddfddt;
  c.ddsddt = ddsddt;
  c.ddfddr = ddfddr;
  c.sed = sed;
  c.sfd = sfd;
  c.spd = spd;
  c.svd = svd;
  c.scd = scd;
  c.pnewdt = pnewdt;
  mj_adapter::run_call(kUinter, ciname, lenCiname, c);
}
