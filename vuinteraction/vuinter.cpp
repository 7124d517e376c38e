// VUINTER (Abaqus/Explicit contact pairs): unpacks the argument list into the
// adapter's block (adapter/explicit_block.hpp, where Abaqus/Explicit's signs
// meet the law's) and runs the adapters' skeleton (adapter/guard.hpp).
// Compiled once per precision, as vuinteraction.cpp.
//
// The penetration of slave node k is rdisp(1,k) (> 0 penetration, < 0 gap);
// its state is statev(:,k). Errors: as VUINTERACTION (vuinteraction.cpp).
#include "vuinteraction.h"

#include "adapter/explicit_routines.hpp"

extern "C" void vuinter_(
    mj_real* sfd, mj_real* scd, mj_real* spd, mj_real* svd,
    mj_real* stress, mj_real* fluxSlv, mj_real* fluxMst, mj_real* sed, mj_real* statev,
    const int* /*kStep*/, const int* /*kInc*/,
    const int* /*nFacNod*/, const int* nSlvNod, const int* /*nMstNod*/,
    const int* /*nSurfDir*/, const int* nDir, const int* nStateVar,
    const int* nProps, const int* /*nTemp*/, const int* /*nPred*/,
    const int* /*numDefTfv*/,
    const int* jSlvUid, const int* /*jMstUid*/, const int* /*jConMstid*/,
    const mj_real* /*timStep*/, const mj_real* /*timGlb*/, const mj_real* /*dTimCur*/,
    const char* surfInt, const char* /*surfSlv*/, const char* /*surfMst*/,
    const mj_real* rdisp, const mj_real* drdisp, const mj_real* drot,
    const mj_real* /*stiffDflt*/, const mj_real* /*condDflt*/, const mj_real* /*shape*/,
    const mj_real* /*coordSlv*/, const mj_real* /*coordMst*/, const mj_real* /*alocaldir*/,
    const mj_real* props, const mj_real* /*areaSlv*/,
    const mj_real* /*tempSlv*/, const mj_real* /*dtempSlv*/,
    const mj_real* /*preDefSlv*/, const mj_real* /*dpreDefSlv*/,
    const mj_real* /*tempMst*/, const mj_real* /*dtempMst*/,
    const mj_real* /*preDefMst*/, const mj_real* /*dpreDefMst*/,
    int lenSurfInt, int /*lenSurfSlv*/, int /*lenSurfMst*/) {
  mj_adapter::ExplicitBlock<mj_real> b;
  b.counts = {*nDir, 1, *nStateVar, *nProps};
  b.n_points = *nSlvNod;
  b.state_stride = *nStateVar;
  b.penetration = rdisp;  // rdisp(1,k)
  b.penetration_stride = *nDir;
  b.d_rel_disp = drdisp;
  b.d_rot = drot;
  b.node = jSlvUid;
  b.props = props;
  b.set_outputs(stress, statev, sed, spd, sfd, scd, svd, fluxSlv, fluxMst);
  mj_adapter::run_call(mj_adapter::explicit_routine("VUINTER", "nStateVar", "drot"), surfInt, lenSurfInt, b);
}
