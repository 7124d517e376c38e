/* The Abaqus user-subroutine interfaces (Explicit: VUINTERACTION, VUINTER;
 * Standard: UINTER), declared once, as Abaqus passes them: every argument by
 * reference, lower-case symbols with a trailing underscore, one hidden length
 * per CHARACTER argument after all others. Every REAL argument is mj_real,
 * float unless MJ_DOUBLE_PRECISION is defined; INTEGER arguments are int.
 * Confidence in each list, the hidden lengths' width, and how to check them
 * against a release: docs/abaqus.md and docs/adapters.md, section 12.
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

/* VUINTER: contact pairs. Arrays are column-major with the slave-node index
 * last; one call covers every node of the slave surface. */
void vuinter_(
    /* write only */
    mj_real* sfd,                /* (nSlvNod) increment of frictional dissipation */
    mj_real* scd,                /* (nSlvNod) increment of creep dissipation */
    mj_real* spd,                /* (nSlvNod) increment of plastic dissipation */
    mj_real* svd,                /* (nSlvNod) increment of viscous dissipation */
    /* read/write */
    mj_real* stress,             /* (nDir, nSlvNod) pressure positive, then shear */
    mj_real* fluxSlv,            /* (nSlvNod) */
    mj_real* fluxMst,            /* (nSlvNod) */
    mj_real* sed,                /* (nSlvNod) elastic energy density */
    mj_real* statev,             /* (nStateVar, nSlvNod) */
    /* read only */
    const int* kStep, const int* kInc,
    const int* nFacNod, const int* nSlvNod, const int* nMstNod,
    const int* nSurfDir, const int* nDir, const int* nStateVar,
    const int* nProps, const int* nTemp, const int* nPred,
    const int* numDefTfv,
    const int* jSlvUid,          /* (nSlvNod) user node numbers */
    const int* jMstUid,          /* (nMstNod) */
    const int* jConMstid,        /* (nFacNod, nSlvNod) */
    const mj_real* timStep, const mj_real* timGlb, const mj_real* dTimCur,
    const char* surfInt,         /* CHARACTER*80 */
    const char* surfSlv,         /* CHARACTER*80 */
    const char* surfMst,         /* CHARACTER*80 */
    const mj_real* rdisp,        /* (nDir, nSlvNod) rdisp(1) > 0: penetration */
    const mj_real* drdisp,       /* (nDir, nSlvNod) increment of relative displacement */
    const mj_real* drot,         /* (2, 2, nSlvNod) */
    const mj_real* stiffDflt,    /* (nSlvNod) */
    const mj_real* condDflt,     /* (nSlvNod) */
    const mj_real* shape,        /* (nFacNod, nSlvNod) */
    const mj_real* coordSlv,     /* (nDir, nSlvNod) */
    const mj_real* coordMst,     /* (nDir, nMstNod) */
    const mj_real* alocaldir,    /* (nDir, nDir, nSlvNod) */
    const mj_real* props,        /* (nProps) */
    const mj_real* areaSlv,      /* (nSlvNod) */
    const mj_real* tempSlv,      /* (nSlvNod) */
    const mj_real* dtempSlv,     /* (nSlvNod) */
    const mj_real* preDefSlv,    /* (nPred, nSlvNod) */
    const mj_real* dpreDefSlv,   /* (nPred, nSlvNod) */
    const mj_real* tempMst,      /* (numDefTfv) */
    const mj_real* dtempMst,     /* (numDefTfv) */
    const mj_real* preDefMst,    /* (nPred, numDefTfv) */
    const mj_real* dpreDefMst,   /* (nPred, numDefTfv) */
    /* hidden CHARACTER lengths */
    int lenSurfInt, int lenSurfSlv, int lenSurfMst);

/* UINTER: Abaqus/Standard, contact pairs (*SURFACE INTERACTION, USER,
 * PROPERTIES=n, DEPVAR=m); one call per contact point and iteration.
 * Abaqus/Standard is always double precision, so every REAL argument is
 * double whatever MJ_DOUBLE_PRECISION says. Argument list of current
 * releases (with AMKI, AMSKI and FREQR; older releases lack them); order
 * [verified] against public working UINTER code, see docs/abaqus.md
 * "Using it in Abaqus/Standard". What the routine does with the arguments is
 * documented in adapter/standard_point.hpp and docs/abaqus.md. */
void uinter_(
    /* to be defined */
    double* stress,       /* (NDIR) pressure positive, then shear; in: start of increment */
    double* ddsddr,       /* (NDIR,NDIR) d STRESS / d RDISP */
    double* amki,         /* (NDIR,NDIR) not used */
    double* amski,        /* (NDIR,NDIR) not used */
    double* flux,         /* (2) set to 0: no heat */
    double* ddfddt,       /* (2,2) set to 0 */
    double* ddsddt,       /* (NDIR,2) set to 0 */
    double* ddfddr,       /* (2,NDIR) set to 0 */
    /* can be defined */
    double* statev,       /* (NSTATV) in: start of increment, out: end */
    double* sed,          /* elastic energy density */
    double* sfd,          /* increment of frictional dissipation */
    double* spd,          /* increment of plastic dissipation */
    double* svd,          /* increment of viscous dissipation */
    double* scd,          /* increment of creep dissipation */
    double* pnewdt,       /* < 1 asks for a smaller increment */
    /* for information */
    const double* rdisp,  /* (NDIR) end of increment: RDISP(1) > 0 penetration, then accumulated slips */
    const double* drdisp, /* (NDIR) increment of RDISP */
    const double* temp, const double* dtemp,     /* (2) */
    const double* predef, const double* dpred,   /* (2,NPRED) */
    const double* time,   /* (2) step, total time at the end of the increment */
    const double* dtime,
    const double* freqr,
    const char* ciname,   /* CHARACTER*80 surface interaction name */
    const char* slname,   /* CHARACTER*80 */
    const char* msname,   /* CHARACTER*80 */
    const double* props,  /* (NPROPS) */
    const double* coords, /* (MCRD) */
    const double* alocaldir, /* (MCRD,MCRD) */
    const double* drot,   /* (2,2) */
    const double* area, const double* chrlngth,
    const int* node, const int* ndir, const int* nstatv, const int* npred, const int* nprops,
    const int* mcrd, const int* kstep, const int* kinc, const int* kit, const int* linper,
    int* lopenclose, int* lstate, int* lsdi, /* not used: left as they come */
    const int* lprint,
    /* hidden CHARACTER lengths */
    int lenCiname, int lenSlname, int lenMsname);

#ifdef __cplusplus
}
#endif

#endif /* MJ_VUINTERACTION_H */
