// VUINTERACTION (Abaqus/Explicit general contact): unpacks the argument list
// into the adapter's block (adapter/explicit_block.hpp, where Abaqus/Explicit's
// signs meet the law's) and runs the adapters' skeleton (adapter/guard.hpp).
// Compiled once per precision (mj_real = float, or double with
// MJ_DOUBLE_PRECISION); the law itself always runs in double precision.
// The rest: docs/adapters.md, section 9.
#include "vuinteraction.h"

#include "adapter/explicit_routines.hpp"

extern "C" void vuinteraction_(
    mj_real* stress, mj_real* fluxSlv, mj_real* fluxMst, mj_real* state, mj_real* sed,
    mj_real* sfd, mj_real* scd, mj_real* spd, mj_real* svd,
    const int* nBlock, const int* /*nBlockAnal*/, const int* /*nBlockEdge*/,
    const int* nNodState, const int* nNodSlv, const int* /*nNodMst*/,
    const int* nDir, const int* nStates, const int* nProps,
    const int* /*nTemp*/, const int* /*nFields*/,
    const int* /*jFlags*/, const mj_real* /*rData*/,
    const char* surfInt, const char* /*surfSlv*/, const char* /*surfMst*/,
    const int* jConSlvUid, const int* /*jConMstUid*/,
    const mj_real* props, const mj_real* penetration, const mj_real* drDisp,
    const mj_real* dRot, const mj_real* /*dircos*/, const mj_real* /*stiffDflt*/,
    const mj_real* /*condDflt*/, const mj_real* /*areaSlv*/, const mj_real* /*dircosSl*/,
    const mj_real* /*shapeSlv*/, const mj_real* /*shapeMst*/,
    const mj_real* /*coordSlv*/, const mj_real* /*coordMst*/,
    const mj_real* /*velSlv*/, const mj_real* /*velMst*/,
    const mj_real* /*tempSlv*/, const mj_real* /*tempMst*/,
    const mj_real* /*fieldSlv*/, const mj_real* /*fieldMst*/,
    int lenSurfInt, int /*lenSurfSlv*/, int /*lenSurfMst*/) {
  mj_adapter::ExplicitBlock<mj_real> b;
  b.counts = {*nDir, *nNodState, *nStates, *nProps};
  b.n_points = *nBlock;
  b.state_stride = static_cast<long>(*nStates) * *nNodState;  // state(:,1,k): first node state of point k
  b.penetration = penetration;
  b.d_rel_disp = drDisp;
  b.d_rot = dRot;
  b.node = *nNodSlv >= 1 ? jConSlvUid : nullptr;
  b.node_stride = *nNodSlv;
  b.props = props;
  b.set_outputs(stress, state, sed, spd, sfd, scd, svd, fluxSlv, fluxMst);
  mj_adapter::run_call(mj_adapter::explicit_routine("VUINTERACTION", "nStates", "dRot"), surfInt, lenSurfInt, b);
}
