c     Calls UINTER the way Abaqus/Standard calls user subroutines:
c     implicit typing from a stand-in aba_param.inc (double precision),
c     every argument by reference, CHARACTER*80 names whose hidden
c     lengths the compiler appends, one contact point per call, and
c     several calls per increment (equilibrium iterations), each with
c     the state at the START of the increment.
c
c     Usage: uinter_caller <records-file>
c
c     For each point of a run, nstep increments of three iterations:
c       1. RDISP at the start of the increment, DRDISP = 0 (Abaqus's
c          first iteration);
c       2. an overshooting estimate, 1.5 times the increment;
c       3. the converged RDISP, then the same call once more.
c     The program stops with code 2 if the two calls of iteration 3 do
c     not give identical outputs (a repeated call must not commit
c     anything), if iteration 1 does not return the start traction, or
c     if any call asks for a smaller increment (PNEWDT < 1) on these
c     moderate paths. Every converged call is written to the records
c     file; uinter_compare recomputes it with the law library.
      program uincll
      include 'aba_param.inc'
      character*256 outfil
      dimension props(20)
c     Almeida, Lourenco & Barros, mortar M15 (paper, Table 1), then the
c     optional controls: scheme 3 (implicit), defaults, shear sign +1.
      data props /741.1d0, 308.8d0, 1.78d0, 2.67d0, 0.01209d0,
     *   0.121d0, 40.d0, 32.d0, 511.9d0, 8.d0, 0.d0, 856.1d0,
     *   10.d0, 3.d0, 3.d0, 0.d0, 0.d0, 0.d0, 0.d0, 1.d0/
c
      call get_command_argument(1, outfil)
      if (len_trim(outfil) .eq. 0) stop 1
      open (10, file=outfil, status='replace', action='write')
      nbad = 0
c     The 14 parameters only (defaults: implicit, shear sign +1), 3D.
      call urun(10, 'U3  ', 3, 14, props, nbad)
c     All 20 values, 2D.
      call urun(10, 'U2  ', 2, 20, props, nbad)
c     Modified Euler inside UINTER (continuum tangent), 3D.
      props(15) = 1.d0
      call urun(10, 'U3E ', 3, 20, props, nbad)
      close (10)
      if (nbad .ne. 0) then
         write (*,*) 'UINTER: failed checks:', nbad
         stop 2
      end if
      write (*,*) 'UINTER: repeated calls identical, no cut-backs'
      end
c
c     Loading path of point k at time t in [0,1]: penetration (Abaqus
c     sign, > 0 overlap) and the two accumulated slips. At t = 0 the
c     point has a point-dependent penetration p0 (its initial gap or
c     overclosure), which becomes its reference.
      subroutine path(k, t, pen, s1, s2)
      include 'aba_param.inc'
      parameter (pi = 3.14159265358979d0)
      itype = mod(k-1, 6) + 1
      p0 = 1.d-4*mod(k, 5)
      ramp = min(1.d0, 10.d0*t)
      s1 = 0.d0
      s2 = 0.d0
      if (itype .eq. 1) then
c        pure opening into softening
         dn = 0.01d0*t
      else if (itype .eq. 2) then
c        open, close into compression, reopen
         dn = 0.006d0*sin(2.d0*pi*t)
      else if (itype .eq. 3) then
c        pressed (about -0.5 MPa), then sheared along t1
         dn = -7.d-4*ramp
         s1 = 0.02d0*max(0.d0, t - 0.1d0)
      else if (itype .eq. 4) then
c        pressed harder, sheared diagonally
         dn = -1.3d-3*ramp
         s1 = 0.015d0*t
         s2 = 0.015d0*t
      else if (itype .eq. 5) then
c        cyclic shear under light pressure
         dn = -5.d-4*ramp
         s1 = 0.01d0*sin(4.d0*pi*t)
      else
c        opening and shearing together
         dn = 3.d-3*t
         s1 = 4.d-3*t
         s2 = -3.d-3*t
      end if
      pen = p0 - dn
      return
      end
c
c     One UINTER call with neutral values for what the law does not read.
      subroutine call1(cint, ndir, nprops, props, stress, ddsddr,
     *   statev, sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp,
     *   node, kinc, kit)
      include 'aba_param.inc'
      parameter (nstatv = 23, npred = 1, mcrd = 3)
      character*80 cint, cslv, cmst
      dimension props(nprops), stress(ndir), ddsddr(ndir,ndir),
     *   statev(nstatv), rdisp(ndir), drdisp(ndir)
      dimension amki(3,3), amski(3,3), flux(2), ddfddt(2,2),
     *   ddsddt(3,2), ddfddr(2,3), temp(2), dtemp(2),
     *   predef(2,npred), dpred(2,npred), time(2), coords(mcrd),
     *   alocal(mcrd,mcrd), drot(2,2)
      cslv = 'BRICK-TOP'
      cmst = 'BRICK-BOTTOM'
      amki = 0
      amski = 0
      flux = 0
      ddfddt = 0
      ddsddt = 0
      ddfddr = 0
      temp = 0
      dtemp = 0
      predef = 0
      dpred = 0
      time = 0
      dtime = 1.d-2
      freqr = 0
      coords = 0
      alocal = 0
      drot = 0
      drot(1,1) = 1
      drot(2,2) = 1
      area = 1
      chrlen = 10
      nstv = nstatv
      npr = npred
      mcr = mcrd
      kstep = 1
      linper = 0
      lopcl = -1
      lstate = -1
      lsdi = 0
      lprint = 0
      call uinter(stress, ddsddr, amki, amski, flux, ddfddt, ddsddt,
     *   ddfddr, statev, sed, sfd, spd, svd, scd, pnewdt, rdisp,
     *   drdisp, temp, dtemp, predef, dpred, time, dtime, freqr,
     *   cint, cslv, cmst, props, coords, alocal, drot, area, chrlen,
     *   node, ndir, nstv, npr, nprops, mcr, kstep, kinc, kit, linper,
     *   lopcl, lstate, lsdi, lprint)
      return
      end
c
c     Writes one converged call: tag, increment, point, nDir, then 70
c     reals: rdisp(1..3), drdisp(1..3), start state(1..23),
c     stress(1..3), ddsddr(1..3,1..3), sed, spd, sfd, svd, scd, pnewdt,
c     end state(1..23). Missing components are written as 0.
      subroutine record(iout, tag, istep, k, ndir, rdisp, drdisp, st0,
     *   stress, ddsddr, sed, spd, sfd, svd, scd, pnewdt, st1)
      include 'aba_param.inc'
      parameter (nstate = 23)
      character*4 tag
      dimension rdisp(ndir), drdisp(ndir), st0(nstate), stress(ndir),
     *   ddsddr(ndir,ndir), st1(nstate), v(70)
      v = 0
      v(1:ndir) = rdisp
      v(4:3+ndir) = drdisp
      v(7:29) = st0
      v(30:29+ndir) = stress
      do 10 j = 1, ndir
         v(33+3*(j-1):32+3*(j-1)+ndir) = ddsddr(:,j)
   10 continue
      v(42:47) = (/ sed, spd, sfd, svd, scd, pnewdt /)
      v(48:70) = st1
      call wcall(iout, tag, istep, k, ndir, 70, v)
      return
      end
c
c     One run: npt points, each its own sequence of increments.
      subroutine urun(iout, tag, ndir, nprops, props, nbad)
      include 'aba_param.inc'
      parameter (npt = 6, nstate = 23, nstep = 40)
      character*4 tag
      character*80 cint
      dimension props(nprops)
      dimension statev(nstate), st0(nstate), stw(nstate),
     *   stress(3), ddsddr(3,3), rdisp(3), drdisp(3), r0(3), r1(3),
     *   sa(3), da(9), sta(nstate), stress0(3)
      cint = 'MORTAR-STD'
      call wprops(iout, tag, nprops, props)
      do 200 k = 1, npt
         node = 3000 + k
         statev = 0
         stress = 0
         sed = 0
         do 100 istep = 1, nstep
            kinc = istep
            t0 = istep - 1
            t0 = t0/nstep
            t1 = istep
            t1 = t1/nstep
            call path(k, t0, r0(1), r0(2), r0(3))
            call path(k, t1, r1(1), r1(2), r1(3))
            st0 = statev
            do 5 i = 1, ndir
               stress0(i) = stress(i)
    5       continue
c           Iteration 1: no increment yet.
            do 10 i = 1, ndir
               rdisp(i) = r0(i)
               drdisp(i) = 0
   10       continue
            stw = st0
            pnewdt = 1.d36
            call call1(cint, ndir, nprops, props, stress, ddsddr, stw,
     *         sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp, node,
     *         kinc, 0)
            if (pnewdt .lt. 1) nbad = nbad + 1
c           From the second increment on, the start traction comes back.
            if (istep .gt. 1) then
               do 15 i = 1, ndir
                  if (abs(stress(i) - stress0(i)) .gt.
     *                1.d-12*(abs(stress0(i)) + 1)) nbad = nbad + 1
   15          continue
            end if
c           Iteration 2: an overshooting estimate.
            do 20 i = 1, ndir
               drdisp(i) = 1.5d0*(r1(i) - r0(i))
               rdisp(i) = r0(i) + drdisp(i)
   20       continue
            stw = st0
            pnewdt = 1.d36
            call call1(cint, ndir, nprops, props, stress, ddsddr, stw,
     *         sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp, node,
     *         kinc, 1)
c           Iteration 3: converged, called twice from the start state.
            do 30 i = 1, ndir
               rdisp(i) = r1(i)
               drdisp(i) = r1(i) - r0(i)
   30       continue
            sta = st0
            pnewdt = 1.d36
            call call1(cint, ndir, nprops, props, stress, ddsddr, sta,
     *         sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp, node,
     *         kinc, 2)
            if (pnewdt .lt. 1) nbad = nbad + 1
            do 45 i = 1, ndir
               sa(i) = stress(i)
               do 40 j = 1, ndir
                  da(i + 3*(j-1)) = ddsddr(i,j)
   40          continue
   45       continue
            sed1 = sed
            spd1 = spd
            statev = st0
            pnewdt = 1.d36
            call call1(cint, ndir, nprops, props, stress, ddsddr,
     *         statev, sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp,
     *         node, kinc, 3)
            do 55 i = 1, ndir
               if (stress(i) .ne. sa(i)) nbad = nbad + 1
               do 50 j = 1, ndir
                  if (ddsddr(i,j) .ne. da(i + 3*(j-1))) nbad = nbad + 1
   50          continue
   55       continue
            do 60 i = 1, nstate
               if (statev(i) .ne. sta(i)) nbad = nbad + 1
   60       continue
            if (sed .ne. sed1 .or. spd .ne. spd1) nbad = nbad + 1
            call record(iout, tag, istep, k, ndir, rdisp, drdisp, st0,
     *         stress, ddsddr, sed, spd, sfd, svd, scd, pnewdt, statev)
  100    continue
  200 continue
      return
      end
