// UINTER of standardU.dll with a property that breaks its rule
// (c0 <= ft0 tan(phi0)): the DLL reports it and calls XIT, which it finds
// exported by this program (exit_utility_stub.cpp). Returning from the call
// means the utility was not called: exit code 1.
#include <cstdio>
#include <cstring>

#include "vuinteraction.h"

int main() {
  double stress[3] = {}, ddsddr[9] = {}, amki[9] = {}, amski[9] = {}, flux[2] = {}, ddfddt[4] = {};
  double ddsddt[6] = {}, ddfddr[6] = {}, statev[23] = {}, sed = 0, sfd = 0, spd = 0, svd = 0, scd = 0;
  double pnewdt = 1e36, rdisp[3] = {}, drdisp[3] = {}, zeros[16] = {}, drot[4] = {1, 0, 0, 1};
  double alocal[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, dtime = 1, area = 1, length = 1;
  // Almeida M15 (Table 1) with c0 = 0.5 MPa < ft0 tan(phi0) = 1.49 MPa.
  double props[14] = {741.1, 308.8, 1.78, 0.5, 0.01209, 0.121, 40., 32., 511.9, 8., 0., 856.1, 10., 3.};
  int node = 1001, ndir = 3, nstatv = 23, npred = 0, nprops = 14, mcrd = 3, kstep = 1, kinc = 1, kit = 1;
  int linper = 0, lopenclose = -1, lstate = -1, lsdi = -1, lprint = 0;
  char name[80];
  std::memset(name, ' ', sizeof name);
  std::memcpy(name, "MORTAR-M15", 10);
  uinter_(stress, ddsddr, amki, amski, flux, ddfddt, ddsddt, ddfddr, statev, &sed, &sfd, &spd, &svd, &scd, &pnewdt,
          rdisp, drdisp, zeros, zeros, zeros, zeros, zeros, &dtime, zeros, name, name, name, props, zeros, alocal,
          drot, &area, &length, &node, &ndir, &nstatv, &npred, &nprops, &mcrd, &kstep, &kinc, &kit, &linper,
          &lopenclose, &lstate, &lsdi, &lprint, 80, 80, 80);
  std::puts("UINTER returned: XIT was not called");
  return 1;
}
