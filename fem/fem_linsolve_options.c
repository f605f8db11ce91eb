/* fem_linsolve_options.c: the sparse solver's default options (fem_linsolve.h), apart from
 * the solvers themselves so that the FE model builds without MUMPS and KLU (cs_fem_kernels). */
#include "fem_linsolve.h"


csfLinSolverOptions csf_linSolverDefault(void) {
  csfLinSolverOptions o;
  o.kind = CSF_SOLVER_MUMPS;
  o.symmetric = 0;
  o.ordering = 7;
  o.threads = 0;
  o.max_threads = 0;
  o.ranks = 1;
  o.pivot_threshold = -1;
  return o;
}
