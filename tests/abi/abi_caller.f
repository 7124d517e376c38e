c     Calls VUINTERACTION and VUINTER the way Abaqus/Explicit calls user
c     subroutines: implicit typing from vaba_param.inc (single or double
c     precision, chosen by the include directory at build time), every
c     argument by reference, CHARACTER*80 names whose hidden lengths the
c     compiler appends, blocks of several points.
c
c     Usage: abi_caller <records-file>
c
c     1. Four runs of nbc points over nstep increments: general contact
c        (VUINTERACTION) and contact pairs (VUINTER), each in 3D and 2D.
c        Every call is written to the records file (inputs, start state,
c        outputs) so that abi_compare can recompute it with the law.
c     2. Block invariance: 512 points integrated as one block, as 512
c        blocks of one point and as one block in shuffled order must give
c        identical results; the program stops with code 2 if they do not.
      program abicll
      include 'vaba_param.inc'
      character*256 outfil
      dimension props(20)
c     Almeida, Lourenco & Barros, mortar M15 (paper, Table 1), then the
c     optional controls: scheme 1, STOL 1e-6, defaults, shear sign +1.
      data props /741.1d0, 308.8d0, 1.78d0, 2.67d0, 0.01209d0,
     *   0.121d0, 40.d0, 32.d0, 511.9d0, 8.d0, 0.d0, 856.1d0,
     *   10.d0, 3.d0, 1.d0, 1.d-6, 0.d0, 0.d0, 0.d0, 1.d0/
c
      call get_command_argument(1, outfil)
      if (len_trim(outfil) .eq. 0) stop 1
      open (10, file=outfil, status='replace', action='write')
c     General contact with the 14 parameters only (default controls).
      call gcrun(10, 'GC3 ', 3, 14, props)
      call gcrun(10, 'GC2 ', 2, 14, props)
c     Contact pairs with all 20 values.
      call cprun(10, 'CP3 ', 3, 20, props)
      call cprun(10, 'CP2 ', 2, 20, props)
      close (10)
c
      call invar(props, nbad)
      if (nbad .ne. 0) then
         write (*,*) 'block invariance: mismatching values:', nbad
         stop 2
      end if
      write (*,*) 'block invariance: identical results'
      end
c
c     Loading path of point k at time t in [0,1]: penetration (Abaqus
c     sign, > 0 overlap) and the two slips. The first call (t = 0) sees
c     a point-dependent penetration p0, which becomes its reference.
      subroutine path(k, t, pen, s1, s2)
      include 'vaba_param.inc'
      parameter (pi = 3.14159265358979d0)
      itype = mod(k-1, 6) + 1
      amp = 1.d0 + 0.1d0*mod(k-1, 7)
      p0 = 1.d-4*mod(k, 5)
      ramp = min(1.d0, 10.d0*t)
      s1 = 0.d0
      s2 = 0.d0
      if (itype .eq. 1) then
c        pure opening to complete separation
         dn = 0.03d0*amp*t
      else if (itype .eq. 2) then
c        open, close into compression, reopen
         dn = 0.008d0*amp*sin(2.d0*pi*t)
      else if (itype .eq. 3) then
c        pressed (about -0.5 MPa), then sheared along t1
         dn = -7.d-4*amp*ramp
         s1 = 0.03d0*amp*max(0.d0, t - 0.1d0)
      else if (itype .eq. 4) then
c        pressed harder, sheared diagonally
         dn = -1.3d-3*amp*ramp
         s1 = 0.02d0*amp*t
         s2 = 0.02d0*amp*t
      else if (itype .eq. 5) then
c        cyclic shear under light pressure
         dn = -5.d-4*amp*ramp
         s1 = 0.01d0*amp*sin(4.d0*pi*t)
      else
c        opening and shearing together
         dn = 4.d-3*amp*t
         s1 = 6.d-3*amp*t
         s2 = -4.d-3*amp*t
      end if
      pen = p0 - dn
      return
      end
c
c     Inputs of increment istep (of nstep) for nblock points: the
c     penetration, the relative displacement increment (drDisp(1) as
c     minus the penetration increment; the adapter must not use it) and
c     the accumulated slips.
      subroutine inputs(istep, nstep, nblock, ndir, pen, drdisp, slip)
      include 'vaba_param.inc'
      dimension pen(nblock), drdisp(ndir,nblock), slip(ndir,nblock)
      t = istep
      t = t/nstep
      tprev = max(istep - 1, 0)
      tprev = tprev/nstep
      do 10 k = 1, nblock
         call path(k, t, p, s1, s2)
         call path(k, tprev, pp, sp1, sp2)
         pen(k) = p
         drdisp(1,k) = -(p - pp)
         drdisp(2,k) = s1 - sp1
         slip(1,k) = p
         slip(2,k) = s1
         if (ndir .eq. 3) then
            drdisp(3,k) = s2 - sp2
            slip(3,k) = s2
         end if
   10 continue
      return
      end
c
c     One VUINTERACTION call for a block of nblock points (node-to-face:
c     nNodState = 1), with neutral values for what the law does not read.
      subroutine callgc(cint, nblock, ndir, nprops, props, stress,
     *   fluxs, fluxm, state, sed, sfd, scd, spd, svd, pen, drdisp)
      include 'vaba_param.inc'
      parameter (nstate = 23, nnodsl = 1, nnodms = 4, nfield = 1)
      character*80 cint, cslv, cmst
      dimension props(nprops), stress(ndir,nblock), fluxs(nblock),
     *   fluxm(nblock), state(nstate,1,nblock), sed(nblock),
     *   sfd(nblock), scd(nblock), spd(nblock), svd(nblock),
     *   pen(nblock), drdisp(ndir,nblock)
      dimension jflags(3), rdata(4), jslvid(nnodsl,nblock),
     *   jmstid(nnodms,nblock), drot(2,2,nblock),
     *   dircos(ndir,ndir,nblock), stfdfl(nblock), cndfl(nblock),
     *   areasl(nblock), dircsl(ndir,nblock), shpslv(nnodsl,1),
     *   shpmst(nnodms,nblock), crdslv(ndir,nnodsl,nblock),
     *   crdmst(ndir,nnodms,nblock), velslv(ndir,nnodsl,nblock),
     *   velmst(ndir,nnodms,nblock), tmpslv(nblock), tmpmst(nblock),
     *   fldslv(nfield,nblock), fldmst(nfield,nblock)
      cslv = ' '
      cmst = ' '
      nblkan = nblock
      nblked = 1
      nnodst = 1
      nstates = nstate
      ntemp = 0
      jflags = 0
      rdata = 0
      rdata(3) = 1.d-6
      do 10 k = 1, nblock
         jslvid(1,k) = 1000 + k
   10 continue
      jmstid = 0
c     the unit matrix: the tangent directions do not turn
      drot = 0
      drot(1,1,:) = 1
      drot(2,2,:) = 1
      dircos = 0
      stfdfl = 1.d3
      cndfl = 0
      areasl = 1
      dircsl = 0
      shpslv = 1
      shpmst = 0.25d0
      crdslv = 0
      crdmst = 0
      velslv = 0
      velmst = 0
      tmpslv = 0
      tmpmst = 0
      fldslv = 0
      fldmst = 0
      call vuinteraction(stress, fluxs, fluxm, state, sed,
     *   sfd, scd, spd, svd,
     *   nblock, nblkan, nblked, nnodst, nnodsl, nnodms, ndir,
     *   nstates, nprops, ntemp, nfield,
     *   jflags, rdata,
     *   cint, cslv, cmst,
     *   jslvid, jmstid, props,
     *   pen, drdisp, drot, dircos, stfdfl, cndfl, areasl, dircsl,
     *   shpslv, shpmst, crdslv, crdmst, velslv, velmst,
     *   tmpslv, tmpmst, fldslv, fldmst)
      return
      end
c
c     Writes one record: routine tag, increment, point, nDir, then 60
c     reals: penetration, drDisp(1..3), start state(1..23),
c     stress(1..3), sed, spd, sfd, scd, svd, fluxSlv, fluxMst, end
c     state(1..23). Missing third components are written as 0.
      subroutine record(iout, tag, istep, k, ndir, pen, dd, st0,
     *   stress, sed, spd, sfd, scd, svd, fluxs, fluxm, st1)
      include 'vaba_param.inc'
      parameter (nstate = 23)
      character*4 tag
      dimension dd(ndir), st0(nstate), stress(ndir), st1(nstate),
     *   v(60)
      v = 0
      v(1) = pen
      v(2:1+ndir) = dd
      v(5:27) = st0
      v(28:27+ndir) = stress
      v(31:37) = (/ sed, spd, sfd, scd, svd, fluxs, fluxm /)
      v(38:60) = st1
      call wcall(iout, tag, istep, k, ndir, 60, v)
      return
      end
c
c     VUINTERACTION run: nbc points, one block per increment.
      subroutine gcrun(iout, tag, ndir, nprops, props)
      include 'vaba_param.inc'
      parameter (nbc = 8, nstate = 23, nstep = 80)
      character*4 tag
      character*80 cint
      dimension props(nprops)
      dimension stress(ndir,nbc), fluxs(nbc), fluxm(nbc),
     *   state(nstate,1,nbc), st0(nstate,nbc), sed(nbc), sfd(nbc),
     *   scd(nbc), spd(nbc), svd(nbc), pen(nbc), drdisp(ndir,nbc),
     *   slip(ndir,nbc)
      cint = 'MORTAR-JOINT'
      call wprops(iout, tag, nprops, props)
      stress = 0
      state = 0
      sed = 0
      fluxs = 0
      fluxm = 0
      do 100 istep = 0, nstep
         call inputs(istep, nstep, nbc, ndir, pen, drdisp, slip)
         st0 = state(:,1,:)
         call callgc(cint, nbc, ndir, nprops, props, stress,
     *      fluxs, fluxm, state, sed, sfd, scd, spd, svd, pen, drdisp)
         do 10 k = 1, nbc
            call record(iout, tag, istep, k, ndir, pen(k),
     *         drdisp(1,k), st0(1,k), stress(1,k), sed(k), spd(k),
     *         sfd(k), scd(k), svd(k), fluxs(k), fluxm(k),
     *         state(1,1,k))
   10    continue
  100 continue
      return
      end
c
c     VUINTER run: a slave surface of nbc nodes, all passed every call.
      subroutine cprun(iout, tag, ndir, nprops, props)
      include 'vaba_param.inc'
      parameter (nbc = 8, nstate = 23, nstep = 80, nfac = 4, nmst = 9)
      character*4 tag
      character*80 cint, cslv, cmst
      dimension props(nprops)
      dimension sfd(nbc), scd(nbc), spd(nbc), svd(nbc),
     *   stress(ndir,nbc), fluxs(nbc), fluxm(nbc), sed(nbc),
     *   statev(nstate,nbc), st0(nstate,nbc), pen(nbc),
     *   jslvid(nbc), jmstid(nmst), jconms(nfac,nbc),
     *   rdisp(ndir,nbc), drdisp(ndir,nbc), drot(2,2,nbc),
     *   stfdfl(nbc), cndfl(nbc), shp(nfac,nbc), crdslv(ndir,nbc),
     *   crdmst(ndir,nmst), alocd(ndir,ndir,nbc), areasl(nbc),
     *   tmpslv(nbc), dtmpsl(nbc), prdslv(1,nbc), dprdsl(1,nbc),
     *   tmpmst(1), dtmpms(1), prdmst(1,1), dprdms(1,1)
      cint = 'MORTAR-PAIR'
      cslv = 'BRICK-TOP'
      cmst = 'BRICK-BOTTOM'
      call wprops(iout, tag, nprops, props)
      kstep = 1
      nfacnd = nfac
      nslvnd = nbc
      nmstnd = nmst
      nsrfdr = ndir - 1
      nstvar = nstate
      ntemp = 0
      npred = 0
      ndftfv = 1
      do 5 k = 1, nbc
         jslvid(k) = 2000 + k
    5 continue
      jmstid = 0
      jconms = 1
      timstp = 0
      timglb = 0
      dtimcr = 1.d-6
      drot = 0
      drot(1,1,:) = 1
      drot(2,2,:) = 1
      stfdfl = 1.d3
      cndfl = 0
      shp = 0.25d0
      crdslv = 0
      crdmst = 0
      alocd = 0
      areasl = 1
      tmpslv = 0
      dtmpsl = 0
      prdslv = 0
      dprdsl = 0
      tmpmst = 0
      dtmpms = 0
      prdmst = 0
      dprdms = 0
      stress = 0
      statev = 0
      sed = 0
      fluxs = 0
      fluxm = 0
      do 100 istep = 0, nstep
         kinc = istep + 1
c        rdisp holds penetration and accumulated slips; drdisp(1) is
c        the increase of penetration here (the adapter ignores it).
         call inputs(istep, nstep, nbc, ndir, pen, drdisp, rdisp)
         do 10 k = 1, nbc
            drdisp(1,k) = -drdisp(1,k)
   10    continue
         st0 = statev
         call vuinter(sfd, scd, spd, svd,
     *      stress, fluxs, fluxm, sed, statev,
     *      kstep, kinc, nfacnd, nslvnd, nmstnd, nsrfdr, ndir, nstvar,
     *      nprops, ntemp, npred, ndftfv,
     *      jslvid, jmstid, jconms, timstp, timglb, dtimcr,
     *      cint, cslv, cmst,
     *      rdisp, drdisp, drot, stfdfl, cndfl,
     *      shp, crdslv, crdmst, alocd, props,
     *      areasl, tmpslv, dtmpsl, prdslv, dprdsl,
     *      tmpmst, dtmpms, prdmst, dprdms)
         do 20 k = 1, nbc
            call record(iout, tag, istep, k, ndir, rdisp(1,k),
     *         drdisp(1,k), st0(1,k), stress(1,k), sed(k), spd(k),
     *         sfd(k), scd(k), svd(k), fluxs(k), fluxm(k),
     *         statev(1,k))
   20    continue
  100 continue
      return
      end
c
c     Block invariance (docs/model.md 10, invariant 8): np points as
c     (a) one block, (b) np blocks of one point, (c) one block holding
c     the points in shuffled order. Counts the values that differ.
      subroutine invar(props, nbad)
      include 'vaba_param.inc'
      parameter (np = 512, nstate = 23, nstep = 40, ndir = 3)
      character*80 cint
      dimension props(20)
      dimension pen(np), drdisp(ndir,np), slip(ndir,np), penc(np),
     *   ddc(ndir,np), sa(nstate,np), sb(nstate,np), sc(nstate,np),
     *   ta(ndir,np), tb(ndir,np), tc(ndir,np), ea(np), eb(np),
     *   ec(np), pa(np), pb(np), pc(np), fs(np), fm(np), w1(np),
     *   w2(np), w3(np), iperm(np)
      cint = 'MORTAR-JOINT-SHUFFLED'
c     263 is odd, hence coprime with 512: a permutation.
      do 5 j = 1, np
         iperm(j) = mod(263*(j-1), np) + 1
    5 continue
      sa = 0
      sb = 0
      sc = 0
      ta = 0
      tb = 0
      tc = 0
      ea = 0
      eb = 0
      ec = 0
      nbad = 0
      do 100 istep = 0, nstep
         call inputs(istep, nstep, np, ndir, pen, drdisp, slip)
c        (a) one block
         call callgc(cint, np, ndir, 20, props, ta, fs, fm, sa, ea,
     *      w1, w2, pa, w3, pen, drdisp)
c        (b) one point per call
         do 10 k = 1, np
            call callgc(cint, 1, ndir, 20, props, tb(1,k), fs(k),
     *         fm(k), sb(1,k), eb(k), w1(k), w2(k), pb(k), w3(k),
     *         pen(k), drdisp(1,k))
   10    continue
c        (c) shuffled: position j holds point iperm(j)
         do 20 j = 1, np
            penc(j) = pen(iperm(j))
            do 15 i = 1, ndir
               ddc(i,j) = drdisp(i,iperm(j))
   15       continue
   20    continue
         call callgc(cint, np, ndir, 20, props, tc, fs, fm, sc, ec,
     *      w1, w2, pc, w3, penc, ddc)
         do 40 j = 1, np
            k = iperm(j)
            do 30 i = 1, nstate
               if (sa(i,k) .ne. sb(i,k)) nbad = nbad + 1
               if (sa(i,k) .ne. sc(i,j)) nbad = nbad + 1
   30       continue
            do 35 i = 1, ndir
               if (ta(i,k) .ne. tb(i,k)) nbad = nbad + 1
               if (ta(i,k) .ne. tc(i,j)) nbad = nbad + 1
   35       continue
            if (ea(k) .ne. eb(k) .or. ea(k) .ne. ec(j)) nbad = nbad + 1
            if (pa(k) .ne. pb(k) .or. pa(k) .ne. pc(j)) nbad = nbad + 1
   40    continue
  100 continue
      return
      end
