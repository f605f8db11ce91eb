/* fem_model.c: the model of the full FE model (fem_model.h): creation, loads, the symmetry
 * test that picks the solver mode. The data (csfData, its solver and the state vector) is
 * fem_data.c: the model alone is what the reduced model's kernels need (fem/CMakeLists.txt,
 * target cs_fem_kernels, without the sparse solvers). */
#include "fem_model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fem_element.h"

double csf_wallTime(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}


csfModel* csf_modelCreate(const csfMesh* mesh, const csfMaterial* mat, csError* err) {
  if (!mesh || !mat || mesh->ntet <= 0) {
    cs_errorSet(err, CS_ERR_ARG, "fem_model: empty mesh or no material");
    return NULL;
  }
  if (!(mat->C10 > 0) || !(mat->C20 >= 0) || !(mat->kappa > 0)) {
    cs_errorSet(err, CS_ERR_ARG, "fem_model: need C10 > 0, C20 >= 0, kappa > 0 (got %g %g %g)",
                mat->C10, mat->C20, mat->kappa);
    return NULL;
  }
  csfModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory");
    return NULL;
  }
  m->mesh = mesh;
  m->mat = *mat;
  m->ndof = 3 * mesh->nnode;
  m->fib_tension_only = 1; /* smoothed tension-only law (csf_fibreLaw) */
  m->fib_split = 1;        /* fibre elements within one host each (fem_fibre.c) */
  m->solver = csf_linSolverDefault();
  m->solver.symmetric = -1; /* LDL^T where the tangent is symmetric (csf_modelSymmetric) */
  const size_t nt = (size_t)mesh->ntet;
  m->dNdX = malloc(nt * 120 * sizeof(double));
  m->wq = malloc(nt * 4 * sizeof(double));
  m->vol = malloc(nt * sizeof(double));
  m->face_p = calloc((size_t)(mesh->nface > 0 ? mesh->nface : 1), sizeof(double));
  m->fixed = calloc((size_t)m->ndof, 1);
  m->u_fix = calloc((size_t)m->ndof, sizeof(double));
  m->f_dead = calloc((size_t)m->ndof, sizeof(double));
  m->face_local = malloc((size_t)(mesh->nface > 0 ? mesh->nface : 1) * 6 * sizeof(int));
  if (!m->dNdX || !m->wq || !m->vol || !m->face_p || !m->fixed || !m->u_fix || !m->f_dead || !m->face_local) {
    csf_modelDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory for %d elements", mesh->ntet);
    return NULL;
  }
  /* reference shape gradients and weights of every element */
  for (size_t e = 0; e < nt; e++) {
    const int* tv = mesh->tet + 10 * e;
    double X[30];
    for (int a = 0; a < 10; a++) {
      memcpy(X + 3 * a, mesh->x + 3 * tv[a], 3 * sizeof(double));
    }
    if (csf_tetReference(X, m->dNdX + 120 * e, m->wq + 4 * e, &m->vol[e]) != 0) {
      csf_modelDestroy(m);
      cs_errorSet(err, CS_ERR_ARG, "fem_model: element %zu is inverted or degenerate", e);
      return NULL;
    }
  }
  /* local index of each face node inside its owning tetrahedron */
  for (int f = 0; f < mesh->nface; f++) {
    const int* tv = mesh->tet + 10 * mesh->face_tet[f];
    for (int k = 0; k < 6; k++) {
      m->face_local[6 * f + k] = -1;
      for (int a = 0; a < 10; a++) {
        if (tv[a] == mesh->face[6 * f + k]) {
          m->face_local[6 * f + k] = a;
        }
      }
    }
  }
  return m;
}


void csf_modelDestroy(csfModel* m) {
  if (!m) {
    return;
  }
  free(m->dNdX), free(m->wq), free(m->vol), free(m->face_p), free(m->fixed), free(m->u_fix);
  free(m->f_dead);
  free(m->fib_node), free(m->fib_coef), free(m->fib_L0), free(m->fib_EA);
  free(m->adj_ptr), free(m->adj), free(m->row_ptr), free(m->col), free(m->tet_map);
  free(m->fib_map), free(m->fib_single), free(m->face_local);
  free(m);
}


int csf_modelAddPressure(csfModel* m, int tag, double p_unit) {
  int n = 0;
  for (int f = 0; f < m->mesh->nface; f++) {
    if (m->mesh->face_tag[f] == tag) {
      m->face_p[f] += p_unit;
      n++;
    }
  }
  return n;
}


typedef struct {
  int a, b;   /* corner nodes of a face edge, a < b */
  double p;   /* pressure per unit load of the face */
} FaceEdge;

static int cmpFaceEdge(const void* x, const void* y) {
  const FaceEdge* e = x;
  const FaceEdge* f = y;
  if (e->a != f->a) {
    return (e->a > f->a) - (e->a < f->a);
  }
  if (e->b != f->b) {
    return (e->b > f->b) - (e->b < f->b);
  }
  return (e->p > f->p) - (e->p < f->p);
}


int csf_modelSymmetric(const csfModel* m) {
  const csfMesh* me = m->mesh;
  int nf = 0;
  for (int f = 0; f < me->nface; f++) {
    nf += m->face_p[f] != 0.0;
  }
  if (nf == 0) {
    return 1;
  }
  FaceEdge* e = malloc((size_t)nf * 3 * sizeof *e);
  if (!e) {
    return 0; /* the safe answer */
  }
  int k = 0;
  for (int f = 0; f < me->nface; f++) {
    if (m->face_p[f] == 0.0) {
      continue;
    }
    const int* fn = me->face + 6 * f;
    for (int j = 0; j < 3; j++) {
      const int a = fn[j], b = fn[(j + 1) % 3];
      e[k].a = a < b ? a : b;
      e[k].b = a < b ? b : a;
      e[k].p = m->face_p[f];
      k++;
    }
  }
  qsort(e, (size_t)k, sizeof *e, cmpFaceEdge);
  /* closed: every (edge, pressure) occurs exactly twice (two faces meet at each edge) */
  int closed = 1;
  for (int i = 0; i < k && closed;) {
    int j = i + 1;
    while (j < k && !cmpFaceEdge(e + i, e + j)) {
      j++;
    }
    closed = j - i == 2;
    i = j;
  }
  free(e);
  return closed;
}
