/* The Abaqus/Explicit user-subroutine interfaces this project implements,
 * declared once, with their argument lists as Abaqus passes them (Fortran
 * convention: every argument by reference, lower-case symbol with a trailing
 * underscore, one hidden length per CHARACTER argument after all others).
 *
 * One source, two precisions: every REAL argument is mj_real, which is float
 * unless MJ_DOUBLE_PRECISION is defined (Abaqus/Explicit double precision).
 * INTEGER arguments (names i-n) are int.
 *
 * Confidence: [verified] / [transcribed] as in the README section "Using it in
 * Abaqus/Explicit", which also says how to check them against your release.
 */
#ifndef MJ_VUINTERACTION_H
#define MJ_VUINTERACTION_H

#ifdef MJ_DOUBLE_PRECISION
typedef double mj_real;
#else
typedef float mj_real;
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* VUINTERACTION: general contact (the primary entry point). Arrays are
 * column-major with the block index last. */
void vuinteraction_(
    /* read/write */
    mj_real* stress,      /* (nDir, nBlock) pressure positive, then shear */
    mj_real* fluxSlv,     /* (nBlock) */
    mj_real* fluxMst,     /* (nBlock) */
    mj_real* state,       /* (nStates, nNodState, nBlock) */
    mj_real* sed,         /* (nBlock) elastic energy density */
    /* write only */
    mj_real* sfd,         /* (nBlock) increment of frictional dissipation */
    mj_real* scd,         /* (nBlock) increment of creep dissipation */
    mj_real* spd,         /* (nBlock) increment of plastic dissipation */
    mj_real* svd,         /* (nBlock) increment of viscous dissipation */
    /* read only */
    const int* nBlock, const int* nBlockAnal, const int* nBlockEdge,
    const int* nNodState, const int* nNodSlv, const int* nNodMst,
    const int* nDir, const int* nStates, const int* nProps,
    const int* nTemp, const int* nFields,
    const int* jFlags,           /* (3) step, increment, contact-type flag */
    const mj_real* rData,        /* (4) step time, total time, dt, tracking thickness */
    const char* surfInt,         /* CHARACTER*80 */
    const char* surfSlv,         /* CHARACTER*80 */
    const char* surfMst,         /* CHARACTER*80 */
    const int* jConSlvUid,       /* (nNodSlv, nBlock) */
    const int* jConMstUid,       /* (nNodMst, nBlockAnal) */
    const mj_real* props,        /* (nProps) */
    const mj_real* penetration,  /* (nBlock) > 0: the surfaces overlap */
    const mj_real* drDisp,       /* (nDir, nBlock) relative displacement increment, local */
    const mj_real* dRot,         /* (2, 2, nBlock) */
    const mj_real* dircos,       /* (nDir, nDir, nBlock) */
    const mj_real* stiffDflt,    /* (nBlock) */
    const mj_real* condDflt,     /* (nBlock) */
    const mj_real* areaSlv,      /* (nBlock) */
    const mj_real* dircosSl,     /* (nDir, nBlock) */
    const mj_real* shapeSlv,     /* (nNodSlv, nBlockEdge) */
    const mj_real* shapeMst,     /* (nNodMst, nBlockAnal) */
    const mj_real* coordSlv,     /* (nDir, nNodSlv, nBlock) */
    const mj_real* coordMst,     /* (nDir, nNodMst, nBlockAnal) */
    const mj_real* velSlv,       /* (nDir, nNodSlv, nBlock) */
    const mj_real* velMst,       /* (nDir, nNodMst, nBlockAnal) */
    const mj_real* tempSlv,      /* (nBlock) */
    const mj_real* tempMst,      /* (nBlockAnal) */
    const mj_real* fieldSlv,     /* (nFields, nBlock) */
    const mj_real* fieldMst,     /* (nFields, nBlockAnal) */
    /* hidden CHARACTER lengths */
    int lenSurfInt, int lenSurfSlv, int lenSurfMst);

#ifdef __cplusplus
}
#endif

#endif /* MJ_VUINTERACTION_H */
