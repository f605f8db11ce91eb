/* bench_rom_legfile.c: the cost of a rom leg read from its file (robot/rom/robot_rom_file.h;
 * not a test: prints numbers; built, not registered).
 *
 *   bench_rom_legfile LEG.h5 [n_rhs] [n_jac]
 *
 * Prints the CPU time of reading the file into the reduced model (no gmsh, no chamber
 * tensors), of building the inertia operators and K_r(0) (csr_romModelCreate), and of one
 * reduced evaluation without and with the tangent at a loaded state (the right-hand side's
 * and the Jacobian's dominant parts in robot_rom.c), averaged over n_rhs and n_jac calls. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "robot_rom.h"
#include "robot_rom_file.h"

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: bench_rom_legfile LEG.h5 [n_rhs] [n_jac]\n");
    return 2;
  }
  const int nr = argc > 2 ? atoi(argv[2]) : 20, nj = argc > 3 ? atoi(argv[3]) : 3;
  csError err = {0};
  csrRomLegFile lf;
  double c0 = cpu();
  if (csr_romLegFileRead(argv[1], &lf, &err) != CS_OK) {
    fprintf(stderr, "bench_rom_legfile: %s\n", err.msg);
    return 1;
  }
  const double c_read = cpu() - c0;
  csrRomParams par = csr_romDefaultParams();
  c0 = cpu();
  csrRomModel* m = csr_romModelCreate(lf.rom, &par, lf.rom->face_ch, &err);
  const double c_model = cpu() - c0;
  if (!m) {
    fprintf(stderr, "bench_rom_legfile: %s\n", err.msg);
    return 1;
  }
  csfRomData* d = csf_romDataCreate(lf.rom, &err);
  csf_romDataReset(lf.rom, d);
  const int n = lf.rom->n;
  for (int k = 0; k < n; k++) {
    d->q[k] = 1e-7 * sin(1.0 + 2.3 * k); /* M-orthonormal basis: q in mm t^0.5, about 1e-4 mm */
  }
  double* face_p = calloc((size_t)lf.mesh->nface, sizeof(double));
  for (int f = 0; f < lf.mesh->nface; f++) {
    face_p[f] = lf.rom->face_ch[f] == 0 || lf.rom->face_ch[f] == 1 ? 0.05 : 0.0;
  }
  csfRomLoad ld = {face_p, {0, -9810, 0}, NULL};
  c0 = cpu();
  int bad = 0;
  for (int i = 0; i < nr; i++) {
    bad |= csf_romEvaluate(lf.rom, d, &ld, 0);
  }
  const double c_rhs = (cpu() - c0) / nr;
  c0 = cpu();
  for (int i = 0; i < nj; i++) {
    bad |= csf_romEvaluate(lf.rom, d, &ld, 1);
  }
  const double c_jac = (cpu() - c0) / nj;
  printf("%s: n = %d, m = %d, %d of %d Tet10 and %d of %d fibre elements kept; |r| %.3g N%s\n",
         argv[1], n, lf.rom->m, lf.rom->nel[0], lf.mesh->ntet, lf.rom->nel[1], lf.model->nfib,
         d->rnorm, bad ? " (an element inverted)" : "");
  printf("CPU: read %.2f s, inertia operators and K_r(0) %.2f s, evaluation %.4f s, with the "
         "tangent %.3f s\n", c_read, c_model, c_rhs, c_jac);
  free(face_p);
  csf_romDataDestroy(d);
  csr_romModelDestroy(m);
  csr_romLegFileFree(&lf);
  return 0;
}
