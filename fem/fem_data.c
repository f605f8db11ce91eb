/* fem_data.c: the data of the full FE model (fem_model.h): csfData with its sparse solver, and
 * the state vector. Apart from fem_model.c so that the model and the element kernels build
 * without the sparse direct solvers (target cs_fem_kernels, fem/CMakeLists.txt). */
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_krylov.h"
#include "fem_model.h"


csfData* csf_dataCreate(const csfModel* m, csError* err) {
  if (m->finalized != 1) { /* CSF_MODEL_KERNELS: no pattern to assemble into */
    cs_errorSet(err, CS_ERR_ARG, "fem_model: csf_modelFinalize must run before csf_dataCreate");
    return NULL;
  }
  csfData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory");
    return NULL;
  }
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet;
  d->ndof = m->ndof;
  d->u = calloc(n, sizeof(double));
  d->r = calloc(n, sizeof(double));
  d->du = calloc(n, sizeof(double));
  d->u_save = calloc(n, sizeof(double));
  d->kval = calloc((size_t)m->nnz, sizeof(double));
  d->theta = calloc(nt, sizeof(double));
  d->pel = calloc(nt, sizeof(double));
  d->vratio = calloc(nt, sizeof(double));
  d->jel = calloc(nt, sizeof(double));
  d->theta_save = calloc(nt, sizeof(double));
  d->u_best = calloc(n, sizeof(double));
  d->theta_best = calloc(nt, sizeof(double));
  d->fib_S_best = calloc((size_t)(m->nfib > 0 ? m->nfib : 1), sizeof(double));
  d->vr0 = calloc(nt, sizeof(double));
  d->gel = calloc(nt * 30, sizeof(double));
  d->g0 = calloc(nt * 30, sizeof(double));
  const size_t nfb = (size_t)(m->nfib > 0 ? m->nfib : 1);
  d->fib_S = calloc(nfb, sizeof(double));
  d->fib_E = calloc(nfb, sizeof(double));
  d->fib_d = calloc(3 * nfb, sizeof(double));
  d->fib_S_save = calloc(nfb, sizeof(double));
  d->fib_E0 = calloc(nfb, sizeof(double));
  d->fib_d0 = calloc(3 * nfb, sizeof(double));
  d->fib_zone = calloc(nfb, 1);
  d->kry_b = malloc(n * sizeof(double));
  d->kry_work = malloc(csf_gmresWorkSize(m->ndof, CSF_KRYLOV_RESTART) * sizeof(double));
  d->fext1 = calloc(n, sizeof(double));
  d->du2 = calloc(n, sizeof(double));
  if (!d->u_best || !d->theta_best || !d->fib_S_best || !d->kry_b || !d->kry_work || !d->fib_zone || !d->fext1 || !d->du2 || !d->u || !d->r || !d->du || !d->u_save ||
      !d->kval || !d->theta || !d->pel || !d->vratio || !d->jel || !d->theta_save || !d->vr0 || !d->gel || !d->g0 || !d->fib_S || !d->fib_E ||
      !d->fib_d || !d->fib_S_save || !d->fib_E0 || !d->fib_d0) {
    csf_dataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (%zu dofs)", n);
    return NULL;
  }
  for (size_t e = 0; e < nt; e++) {
    d->theta[e] = d->vratio[e] = d->jel[e] = 1.0; /* reference state: p = 0 */
  }
  for (int f = 0; f < m->nfib; f++) {
    double dS;
    csf_fibreLaw(m->fib_tension_only, 0.0, &d->fib_S[f], &dS); /* reference state: E = 0 */
    d->fib_zone[f] = 1;
  }
  csfLinSolverOptions lo = m->solver;
  lo.symmetric = lo.symmetric < 0 ? csf_modelSymmetric(m) : lo.symmetric;
  d->ls = csf_linSolverCreate(&lo, m->ndof, m->row_ptr, m->col, err);
  if (!d->ls) {
    csf_dataDestroy(d);
    return NULL;
  }
  return d;
}


void csf_dataDestroy(csfData* d) {
  if (!d) {
    return;
  }
  free(d->u), free(d->r), free(d->du), free(d->u_save), free(d->kval), free(d->theta);
  free(d->pel), free(d->vratio), free(d->jel), free(d->theta_save), free(d->vr0), free(d->gel);
  free(d->g0);
  free(d->fib_S), free(d->fib_E), free(d->fib_d), free(d->fib_S_save), free(d->fib_E0);
  free(d->fib_d0), free(d->fib_zone), free(d->kry_b), free(d->u_best), free(d->theta_best), free(d->fib_S_best), free(d->kry_work), free(d->fext1), free(d->du2);
  csf_linSolverDestroy(d->ls);
  free(d);
}


size_t csf_stateSize(const csfModel* m) {
  return (size_t)m->ndof + 2 * (size_t)m->mesh->ntet + (size_t)m->nfib + 1;
}


void csf_stateGet(const csfModel* m, const csfData* d, double* state) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nf = (size_t)m->nfib;
  memcpy(state, d->u, n * sizeof(double));
  memcpy(state + n, d->theta, nt * sizeof(double));
  memcpy(state + n + nt, d->pel, nt * sizeof(double));
  memcpy(state + n + 2 * nt, d->fib_S, nf * sizeof(double));
  state[n + 2 * nt + nf] = d->load;
}


void csf_stateSet(const csfModel* m, csfData* d, const double* state) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nf = (size_t)m->nfib;
  memcpy(d->u, state, n * sizeof(double));
  memcpy(d->theta, state + n, nt * sizeof(double));
  memcpy(d->pel, state + n + nt, nt * sizeof(double));
  memcpy(d->fib_S, state + n + 2 * nt, nf * sizeof(double));
  d->load = state[n + 2 * nt + nf];
}
