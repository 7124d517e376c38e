// VUINTERACTION of explicitU.dll with a property that breaks its rule
// (c0 <= ft0 tan(phi0)): the DLL reports it and calls XPLB_EXIT, which it
// finds exported by this program (exit_utility_stub.cpp). Returning from the
// call means the utility was not called: exit code 1.
#include <cstdio>
#include <cstring>

#include "vuinteraction.h"

int main() {
  mj_real stress[3] = {}, flux_slv[1] = {}, flux_mst[1] = {}, state[34] = {}, sed[1] = {};
  mj_real sfd[1] = {}, scd[1] = {}, spd[1] = {}, svd[1] = {};
  mj_real zeros[16] = {};
  mj_real d_rot[4] = {1, 0, 0, 1};
  // Almeida M15 (Table 1) with c0 = 0.5 MPa < ft0 tan(phi0) = 1.49 MPa.
  mj_real props[14] = {741.1f, 308.8f, 1.78f, 0.5f, 0.01209f, 0.121f, 40.f, 32.f,
                       511.9f, 8.f, 0.f, 856.1f, 10.f, 3.f};
  mj_real penetration[1] = {0}, dr_disp[3] = {};
  int one = 1, zero = 0, three = 3, n_states = 34, n_props = 14, j_flags[3] = {1, 1, 0}, node[1] = {1001};
  char name[80];
  std::memset(name, ' ', sizeof name);
  std::memcpy(name, "MORTAR-M15", 10);
  vuinteraction_(stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd, &one, &zero, &zero, &one, &one,
                 &zero, &three, &n_states, &n_props, &zero, &zero, j_flags, zeros, name, name, name, node, node,
                 props, penetration, dr_disp, d_rot, zeros, zeros, zeros, zeros, zeros, zeros, zeros, zeros,
                 zeros, zeros, zeros, zeros, zeros, zeros, zeros, 80, 80, 80);
  std::puts("VUINTERACTION returned: XPLB_EXIT was not called");
  return 1;
}
