/* fem_mesh.c: Tet10 meshes: structured box mesher, boundary faces, the MSH 2.2 reader and the
 * folded-element fix (see fem_mesh.h; the actuator's geometry and gmsh run:
 * fem_mesh_actuator.c).
 *
 * Rationale. The actuator mesh comes from gmsh (OpenCASCADE boolean geometry, real tetrahedral
 * mesher), run as a separate program so our binaries stay free of GPL code. Tests use a small
 * structured mesher instead: it needs no external program, is deterministic, and a mapping
 * callback gives curved isoparametric tubes and blocks with known analytic answers. Boundary faces
 * are always recomputed from the tetrahedra (a face that belongs to one tetrahedron only), which
 * fixes their orientation from the owning element; gmsh's Tri6 elements only supply the tags. */
#include "fem_mesh.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* local edge node of a Tet10 for vertices (i, j), VTK order */
static int edgeNode(int i, int j);
/* compute boundary faces of m from its tetrahedra (fills face, face_tet, face_tag = 0) */
static csStatus buildBoundaryFaces(csfMesh* m, csError* err);


static int edgeNode(int i, int j) {
  if (i > j) {
    int t = i;
    i = j;
    j = t;
  }
  static const int tab[4][4] = {{-1, 4, 6, 7}, {4, -1, 5, 8}, {6, 5, -1, 9}, {7, 8, 9, -1}};
  return tab[i][j];
}


void csf_tet10Shape(const double xi[3], double N[10], double dN[30]) {
  /* barycentric L0..L3 with L1 = xi0, L2 = xi1, L3 = xi2; corner N = L(2L-1), edge N = 4 Li Lj */
  const double L[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
  /* dL[k][d]: derivative of L_k with respect to xi_d */
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  static const int ed[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  for (int k = 0; k < 4; k++) {
    if (N) {
      N[k] = L[k] * (2.0 * L[k] - 1.0);
    }
    if (dN) {
      for (int d = 0; d < 3; d++) {
        dN[3 * k + d] = (4.0 * L[k] - 1.0) * dL[k][d];
      }
    }
  }
  for (int e = 0; e < 6; e++) {
    int i = ed[e][0], j = ed[e][1];
    if (N) {
      N[4 + e] = 4.0 * L[i] * L[j];
    }
    if (dN) {
      for (int d = 0; d < 3; d++) {
        dN[3 * (4 + e) + d] = 4.0 * (dL[i][d] * L[j] + L[i] * dL[j][d]);
      }
    }
  }
}


void csf_tri6Shape(double s, double t, double N[6], double dN[12]) {
  const double L0 = 1 - s - t, L1 = s, L2 = t;
  if (N) {
    N[0] = L0 * (2 * L0 - 1), N[1] = L1 * (2 * L1 - 1), N[2] = L2 * (2 * L2 - 1);
    N[3] = 4 * L0 * L1, N[4] = 4 * L1 * L2, N[5] = 4 * L2 * L0;
  }
  if (dN) {
    /* d/ds, d/dt */
    dN[0] = -(4 * L0 - 1), dN[1] = -(4 * L0 - 1);
    dN[2] = 4 * L1 - 1, dN[3] = 0;
    dN[4] = 0, dN[5] = 4 * L2 - 1;
    dN[6] = 4 * (L0 - L1), dN[7] = -4 * L1;
    dN[8] = 4 * L2, dN[9] = 4 * L1;
    dN[10] = -4 * L2, dN[11] = 4 * (L0 - L2);
  }
}


double csf_meshTetVolume(const csfMesh* m, int t) {
  /* 4-point rule (degree 2) on the reference tetrahedron of volume 1/6 */
  const double a = 0.5854101966249685, b = 0.1381966011250105;
  const double q[4][3] = {{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}};
  double vol = 0.0;
  for (int g = 0; g < 4; g++) {
    double dN[30], J[9] = {0};
    csf_tet10Shape(q[g], NULL, dN);
    for (int a2 = 0; a2 < 10; a2++) {
      const double* xa = m->x + 3 * m->tet[10 * t + a2];
      for (int i = 0; i < 3; i++) {
        for (int d = 0; d < 3; d++) {
          J[3 * i + d] += xa[i] * dN[3 * a2 + d];
        }
      }
    }
    double det = J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
                 J[2] * (J[3] * J[7] - J[4] * J[6]);
    vol += det / 24.0;
  }
  return vol;
}


void csf_meshDestroy(csfMesh* m) {
  if (!m) {
    return;
  }
  free(m->x);
  free(m->tet);
  free(m->face);
  free(m->face_tet);
  free(m->face_tag);
  free(m);
}


/* one tetrahedron face during boundary extraction */
typedef struct {
  int key[3]; /* sorted vertex ids */
  int tet, lf; /* owner and local face 0..3 */
} FaceRec;


/* order records whose first member is a sorted vertex triple int key[3] (FaceRec, TagRec) */
static int cmpKey3(const void* pa, const void* pb) {
  const int* a = pa;
  const int* b = pb;
  for (int i = 0; i < 3; i++) {
    if (a[i] != b[i]) {
      return a[i] < b[i] ? -1 : 1;
    }
  }
  return 0;
}


static void sort3(int k[3]) {
  for (int i = 0; i < 2; i++) {
    for (int j = 0; j < 2 - i; j++) {
      if (k[j] > k[j + 1]) {
        int t = k[j];
        k[j] = k[j + 1];
        k[j + 1] = t;
      }
    }
  }
}


/* outward faces of a positively oriented tetrahedron (local vertex ids) */
static const int kTetFace[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};


static csStatus buildBoundaryFaces(csfMesh* m, csError* err) {
  size_t nf = 4 * (size_t)m->ntet;
  FaceRec* rec = malloc(nf * sizeof *rec);
  if (!rec) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_mesh: out of memory for %zu faces", nf);
  }
  for (int t = 0; t < m->ntet; t++) {
    for (int f = 0; f < 4; f++) {
      FaceRec* r = rec + 4 * (size_t)t + f;
      for (int i = 0; i < 3; i++) {
        r->key[i] = m->tet[10 * t + kTetFace[f][i]];
      }
      sort3(r->key);
      r->tet = t;
      r->lf = f;
    }
  }
  qsort(rec, nf, sizeof *rec, cmpKey3);
  /* count faces that occur once */
  int nb = 0;
  for (size_t i = 0; i < nf;) {
    size_t j = i + 1;
    while (j < nf && cmpKey3(rec + i, rec + j) == 0) {
      j++;
    }
    if (j - i == 1) {
      nb++;
    }
    i = j;
  }
  m->nface = nb;
  m->face = malloc((size_t)(nb > 0 ? nb : 1) * 6 * sizeof(int));
  m->face_tet = malloc((size_t)(nb > 0 ? nb : 1) * sizeof(int));
  m->face_tag = calloc((size_t)(nb > 0 ? nb : 1), sizeof(int));
  if (!m->face || !m->face_tet || !m->face_tag) {
    free(rec);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_mesh: out of memory for boundary faces");
  }
  int k = 0;
  for (size_t i = 0; i < nf;) {
    size_t j = i + 1;
    while (j < nf && cmpKey3(rec + i, rec + j) == 0) {
      j++;
    }
    if (j - i == 1) {
      const int* tv = m->tet + 10 * rec[i].tet;
      const int* lv = kTetFace[rec[i].lf];
      int* fc = m->face + 6 * k;
      for (int v = 0; v < 3; v++) {
        fc[v] = tv[lv[v]];
        fc[3 + v] = tv[edgeNode(lv[v], lv[(v + 1) % 3])];
      }
      m->face_tet[k] = rec[i].tet;
      k++;
    }
    i = j;
  }
  free(rec);
  return CS_OK;
}


/* one tagged triangle (its sorted vertex ids) */
typedef struct {
  int key[3];
  int tag;
} TagRec;


/* tag the boundary faces of m whose vertices are one of the ntag records (sorted here) */
static void applyTags(csfMesh* m, TagRec* tags, int ntag) {
  for (int i = 0; i < ntag; i++) {
    sort3(tags[i].key);
  }
  qsort(tags, (size_t)ntag, sizeof *tags, cmpKey3);
  for (int fc = 0; fc < m->nface; fc++) {
    TagRec key;
    memcpy(key.key, m->face + 6 * fc, 3 * sizeof(int));
    sort3(key.key);
    TagRec* hit = ntag ? bsearch(&key, tags, (size_t)ntag, sizeof *tags, cmpKey3) : NULL;
    if (hit) {
      m->face_tag[fc] = hit->tag;
    }
  }
}


csStatus csf_meshFacesTagged(csfMesh* m, int ntag, const int* tri, const int* tag,
                             csError* err) {
  free(m->face), free(m->face_tet), free(m->face_tag);
  m->face = m->face_tet = m->face_tag = NULL;
  m->nface = 0;
  csStatus st = buildBoundaryFaces(m, err);
  if (st != CS_OK || ntag <= 0) {
    return st;
  }
  TagRec* rec = malloc((size_t)ntag * sizeof *rec);
  if (!rec) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_mesh: out of memory for %d face tags", ntag);
  }
  for (int i = 0; i < ntag; i++) {
    memcpy(rec[i].key, tri + 3 * i, 3 * sizeof(int));
    rec[i].tag = tag[i];
  }
  applyTags(m, rec, ntag);
  free(rec);
  return CS_OK;
}


/* deterministic hash to [-0.5, 0.5) for jitter */
static double hashUnit(uint32_t a) {
  a ^= a >> 16;
  a *= 0x7feb352dU;
  a ^= a >> 15;
  a *= 0x846ca68bU;
  a ^= a >> 16;
  return (double)a / 4294967296.0 - 0.5;
}


csfMesh* csf_meshCreateBox(const int n[3], csfMapFn map, void* user, double jitter,
                           csError* err) {
  if (n[0] < 1 || n[1] < 1 || n[2] < 1) {
    cs_errorSet(err, CS_ERR_ARG, "fem_mesh: box needs n >= 1 cells per direction");
    return NULL;
  }
  /* doubled grid: vertices at even indices, edge/face/cell midpoints at odd ones */
  const int g0 = 2 * n[0] + 1, g1 = 2 * n[1] + 1, g2 = 2 * n[2] + 1;
  const size_t ng = (size_t)g0 * g1 * g2;
  const int ntet = 6 * n[0] * n[1] * n[2];
  csfMesh* m = calloc(1, sizeof *m);
  double* xi = malloc(ng * 3 * sizeof *xi);
  int* used = calloc(ng, sizeof *used);
  int* tet = malloc((size_t)ntet * 10 * sizeof *tet);
  if (!m || !xi || !used || !tet) {
    free(m), free(xi), free(used), free(tet);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_mesh: out of memory for box mesh");
    return NULL;
  }
#define GID(i, j, k) (((size_t)(k) * g1 + (size_t)(j)) * g0 + (size_t)(i))
  for (int k = 0; k < g2; k++) {
    for (int j = 0; j < g1; j++) {
      for (int i = 0; i < g0; i++) {
        double* p = xi + 3 * GID(i, j, k);
        p[0] = 0.5 * i / n[0];
        p[1] = 0.5 * j / n[1];
        p[2] = 0.5 * k / n[2];
        /* jitter interior vertices only */
        int interior = i > 0 && j > 0 && k > 0 && i < g0 - 1 && j < g1 - 1 && k < g2 - 1;
        if (jitter > 0 && interior && i % 2 == 0 && j % 2 == 0 && k % 2 == 0) {
          uint32_t s = (uint32_t)GID(i, j, k);
          p[0] += jitter * hashUnit(3 * s + 1) / n[0];
          p[1] += jitter * hashUnit(3 * s + 2) / n[1];
          p[2] += jitter * hashUnit(3 * s + 3) / n[2];
        }
      }
    }
  }
  /* Kuhn split: one tetrahedron per permutation of the axes, all sharing the main diagonal */
  static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int t = 0;
  for (int ck = 0; ck < n[2]; ck++) {
    for (int cj = 0; cj < n[1]; cj++) {
      for (int ci = 0; ci < n[0]; ci++) {
        for (int p = 0; p < 6; p++) {
          int v[4][3];
          v[0][0] = 2 * ci, v[0][1] = 2 * cj, v[0][2] = 2 * ck;
          for (int s = 1; s < 4; s++) {
            memcpy(v[s], v[s - 1], sizeof v[s]);
            v[s][perm[p][s - 1]] += 2;
          }
          /* orientation in xi space (vertices unjittered: sign is the permutation's parity) */
          double e[3][3];
          for (int s = 0; s < 3; s++) {
            for (int d = 0; d < 3; d++) {
              e[s][d] = v[s + 1][d] - v[0][d];
            }
          }
          double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
          if (det < 0) {
            int tmp[3];
            memcpy(tmp, v[1], sizeof tmp);
            memcpy(v[1], v[2], sizeof tmp);
            memcpy(v[2], tmp, sizeof tmp);
          }
          int* tv = tet + 10 * t;
          for (int s = 0; s < 4; s++) {
            tv[s] = (int)GID(v[s][0], v[s][1], v[s][2]);
          }
          for (int a = 0; a < 4; a++) {
            for (int b = a + 1; b < 4; b++) {
              tv[edgeNode(a, b)] =
                  (int)GID((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2);
            }
          }
          t++;
        }
      }
    }
  }
#undef GID
  /* edge nodes at the midpoint of their (possibly jittered) vertices, in xi space */
  for (t = 0; t < ntet; t++) {
    int* tv = tet + 10 * t;
    for (int a = 0; a < 4; a++) {
      for (int b = a + 1; b < 4; b++) {
        int e = tv[edgeNode(a, b)];
        for (int d = 0; d < 3; d++) {
          xi[3 * (size_t)e + d] = 0.5 * (xi[3 * (size_t)tv[a] + d] + xi[3 * (size_t)tv[b] + d]);
        }
      }
    }
    for (int a = 0; a < 10; a++) {
      used[tv[a]] = 1;
    }
  }
  /* compact: keep grid points used by some tetrahedron */
  int nn = 0;
  for (size_t g = 0; g < ng; g++) {
    used[g] = used[g] ? nn++ : -1;
  }
  m->nnode = nn;
  m->ntet = ntet;
  m->x = malloc((size_t)nn * 3 * sizeof *m->x);
  double* xin = malloc((size_t)nn * 3 * sizeof *xin);
  if (!m->x || !xin) {
    free(xi), free(used), free(tet), free(xin), free(m->x), free(m);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_mesh: out of memory for box nodes");
    return NULL;
  }
  for (size_t g = 0; g < ng; g++) {
    if (used[g] >= 0) {
      double* dst = m->x + 3 * (size_t)used[g];
      memcpy(xin + 3 * (size_t)used[g], xi + 3 * g, 3 * sizeof(double));
      if (map) {
        map(user, xi + 3 * g, dst);
      } else {
        memcpy(dst, xi + 3 * g, 3 * sizeof(double));
      }
    }
  }
  for (size_t i = 0; i < (size_t)ntet * 10; i++) {
    tet[i] = used[tet[i]];
  }
  m->tet = tet;
  free(xi);
  free(used);
  if (buildBoundaryFaces(m, err) != CS_OK) {
    free(xin);
    csf_meshDestroy(m);
    return NULL;
  }
  /* tag boundary faces by the side of the unit cube all their vertices lie on */
  const double tol = 1e-12;
  for (int f = 0; f < m->nface; f++) {
    for (int side = 0; side < 6; side++) {
      int d = side / 2;
      double val = (side % 2) ? 1.0 : 0.0;
      int on = 1;
      for (int v = 0; v < 3; v++) {
        on = on && fabs(xin[3 * (size_t)m->face[6 * f + v] + d] - val) < tol;
      }
      if (on) {
        m->face_tag[f] = side + 1;
      }
    }
  }
  free(xin);
  return m;
}


/* ---- gmsh MSH 2.2 reader ---- */

/* skip to a line starting with `tag`; returns 0 if found */
static int seekSection(FILE* f, const char* tag) {
  char line[256];
  size_t n = strlen(tag);
  while (fgets(line, sizeof line, f)) {
    if (!strncmp(line, tag, n)) {
      return 0;
    }
  }
  return -1;
}


csfMesh* csf_meshReadMsh(const char* path, csError* err) {
  FILE* f = fopen(path, "r");
  if (!f) {
    cs_errorSet(err, CS_ERR_IO, "%s: cannot open mesh file", path);
    return NULL;
  }
  csfMesh* m = calloc(1, sizeof *m);
  double* xr = NULL;      /* raw nodes indexed by gmsh id */
  int* newid = NULL;      /* gmsh id -> compact id */
  int* tets = NULL;       /* raw tets (gmsh ids) */
  TagRec* tags = NULL;
  int maxid = 0, ntet = 0, ntag = 0, cap_tet = 0, cap_tag = 0;
  double ver = 0;
  int ft = 0, ds = 0;
  if (!m) {
    goto oom;
  }
  if (seekSection(f, "$MeshFormat") || fscanf(f, "%lf %d %d", &ver, &ft, &ds) != 3 ||
      ver < 2.0 || ver >= 3.0 || ft != 0) {
    cs_errorSet(err, CS_ERR_PARSE, "%s: not a MSH 2.x ASCII file (version %g, type %d)", path,
                ver, ft);
    goto fail;
  }
  int nn = 0;
  if (seekSection(f, "$Nodes") || fscanf(f, "%d", &nn) != 1 || nn <= 0) {
    cs_errorSet(err, CS_ERR_PARSE, "%s: missing or empty $Nodes section", path);
    goto fail;
  }
  /* nodes: ids are usually 1..nn; allow gaps by sizing with the largest id */
  long pos = ftell(f);
  for (int i = 0; i < nn; i++) {
    int id;
    double x, y, z;
    if (fscanf(f, "%d %lf %lf %lf", &id, &x, &y, &z) != 4) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: bad node record %d", path, i + 1);
      goto fail;
    }
    if (id > maxid) {
      maxid = id;
    }
  }
  xr = malloc(((size_t)maxid + 1) * 3 * sizeof *xr);
  newid = malloc(((size_t)maxid + 1) * sizeof *newid);
  if (!xr || !newid) {
    goto oom;
  }
  for (int i = 0; i <= maxid; i++) {
    newid[i] = -1;
  }
  fseek(f, pos, SEEK_SET);
  for (int i = 0; i < nn; i++) {
    int id;
    double x, y, z;
    if (fscanf(f, "%d %lf %lf %lf", &id, &x, &y, &z) != 4) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: bad node record %d", path, i + 1);
      goto fail;
    }
    xr[3 * (size_t)id] = x, xr[3 * (size_t)id + 1] = y, xr[3 * (size_t)id + 2] = z;
  }
  int ne = 0;
  if (seekSection(f, "$Elements") || fscanf(f, "%d", &ne) != 1) {
    cs_errorSet(err, CS_ERR_PARSE, "%s: missing $Elements section", path);
    goto fail;
  }
  for (int e = 0; e < ne; e++) {
    int id, type, nt, tg[16];
    if (fscanf(f, "%d %d %d", &id, &type, &nt) != 3 || nt < 0 || nt > 16) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: bad element record %d", path, e + 1);
      goto fail;
    }
    for (int i = 0; i < nt; i++) {
      if (fscanf(f, "%d", &tg[i]) != 1) {
        cs_errorSet(err, CS_ERR_PARSE, "%s: bad element tags %d", path, id);
        goto fail;
      }
    }
    static const int nper[32] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1,
                                 8, 20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 28, 35};
    if (type < 1 || type > 31) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: element %d has unsupported type %d", path, id, type);
      goto fail;
    }
    int nv[64];
    for (int i = 0; i < nper[type]; i++) {
      if (fscanf(f, "%d", &nv[i]) != 1 || nv[i] < 0 || nv[i] > maxid) {
        cs_errorSet(err, CS_ERR_PARSE, "%s: element %d has a bad node id", path, id);
        goto fail;
      }
    }
    if (type == 4) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: linear tetrahedra found: mesh with -order 2", path);
      goto fail;
    }
    if (type == 11) {
      if (ntet == cap_tet) {
        cap_tet = cap_tet ? 2 * cap_tet : 1024;
        int* nt2 = realloc(tets, (size_t)cap_tet * 10 * sizeof *tets);
        if (!nt2) {
          goto oom;
        }
        tets = nt2;
      }
      memcpy(tets + 10 * (size_t)ntet, nv, 10 * sizeof(int));
      ntet++;
    } else if (type == 9 && nt >= 1) {
      if (ntag == cap_tag) {
        cap_tag = cap_tag ? 2 * cap_tag : 1024;
        TagRec* t2 = realloc(tags, (size_t)cap_tag * sizeof *tags);
        if (!t2) {
          goto oom;
        }
        tags = t2;
      }
      memcpy(tags[ntag].key, nv, 3 * sizeof(int));
      tags[ntag].tag = tg[0];
      ntag++;
    }
  }
  if (ntet == 0) {
    cs_errorSet(err, CS_ERR_PARSE, "%s: no Tet10 elements (type 11)", path);
    goto fail;
  }
  /* compact nodes used by tetrahedra */
  int nnode = 0;
  for (size_t i = 0; i < (size_t)ntet * 10; i++) {
    if (newid[tets[i]] < 0) {
      newid[tets[i]] = nnode++;
    }
  }
  m->nnode = nnode;
  m->ntet = ntet;
  m->x = malloc((size_t)nnode * 3 * sizeof *m->x);
  m->tet = malloc((size_t)ntet * 10 * sizeof *m->tet);
  if (!m->x || !m->tet) {
    goto oom;
  }
  for (int i = 0; i <= maxid; i++) {
    if (newid[i] >= 0) {
      memcpy(m->x + 3 * (size_t)newid[i], xr + 3 * (size_t)i, 3 * sizeof(double));
    }
  }
  for (int t = 0; t < ntet; t++) {
    const int* src = tets + 10 * (size_t)t;
    int* dst = m->tet + 10 * (size_t)t;
    /* gmsh Tet10 edge order (0,1) (1,2) (2,0) (3,0) (3,2) (3,1) -> VTK (0,1) (1,2) (0,2) (0,3)
     * (1,3) (2,3): slots 8 and 9 swap (verified on gmsh 4.8 output: all straight elements
     * match exactly, none under the VTK order) */
    static const int g2v[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
    for (int a = 0; a < 10; a++) {
      dst[a] = newid[src[g2v[a]]];
    }
    /* orientation from the straight (vertex) tetrahedron: a folded curved element must not flip it */
    double e3[3][3];
    for (int k = 0; k < 3; k++) {
      for (int d = 0; d < 3; d++) {
        e3[k][d] = m->x[3 * dst[k + 1] + d] - m->x[3 * dst[0] + d];
      }
    }
    double det0 = e3[0][0] * (e3[1][1] * e3[2][2] - e3[1][2] * e3[2][1]) -
                  e3[0][1] * (e3[1][0] * e3[2][2] - e3[1][2] * e3[2][0]) +
                  e3[0][2] * (e3[1][0] * e3[2][1] - e3[1][1] * e3[2][0]);
    if (det0 < 0) {
      /* swap vertices 1 and 2 (and the edge nodes that follow them) */
      int* d = dst;
      int tmp = d[1];
      d[1] = d[2], d[2] = tmp;
      tmp = d[4], d[4] = d[6], d[6] = tmp; /* (0,1) <-> (0,2) */
      tmp = d[8], d[8] = d[9], d[9] = tmp; /* (1,3) <-> (2,3) */
    }
  }
  if (buildBoundaryFaces(m, err) != CS_OK) {
    goto fail;
  }
  /* tags from gmsh triangles */
  for (int i = 0; i < ntag; i++) {
    for (int v = 0; v < 3; v++) {
      tags[i].key[v] = newid[tags[i].key[v]];
    }
  }
  applyTags(m, tags, ntag);
  fclose(f);
  free(xr), free(newid), free(tets), free(tags);
  return m;
oom:
  cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory reading mesh", path);
fail:
  fclose(f);
  free(xr), free(newid), free(tets), free(tags);
  csf_meshDestroy(m);
  return NULL;
}


/* smallest ratio detJ(xi) / detJ_straight over vertices, edge nodes and quadrature points */
static double tetQuality(const csfMesh* m, int t) {
  static const double pts[14][3] = {
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0},
      {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}, {0.1381966011250105, 0.1381966011250105,
      0.1381966011250105}, {0.5854101966249685, 0.1381966011250105, 0.1381966011250105},
      {0.1381966011250105, 0.5854101966249685, 0.1381966011250105},
      {0.1381966011250105, 0.1381966011250105, 0.5854101966249685}};
  const int* tv = m->tet + 10 * t;
  double e[3][3];
  for (int k = 0; k < 3; k++) {
    for (int d = 0; d < 3; d++) {
      e[k][d] = m->x[3 * tv[k + 1] + d] - m->x[3 * tv[0] + d];
    }
  }
  double det0 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  double q = INFINITY;
  for (int p = 0; p < 14; p++) {
    double dN[30], J[9] = {0};
    csf_tet10Shape(pts[p], NULL, dN);
    for (int a = 0; a < 10; a++) {
      const double* xa = m->x + 3 * tv[a];
      for (int i = 0; i < 3; i++) {
        for (int d = 0; d < 3; d++) {
          J[3 * i + d] += xa[i] * dN[3 * a + d];
        }
      }
    }
    double det = J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
                 J[2] * (J[3] * J[7] - J[4] * J[6]);
    q = fmin(q, det / det0);
  }
  return q;
}


int csf_meshFixInverted(csfMesh* m) {
  /* 5 % of the straight element's Jacobian: below this the element is nearly folded and its
   * stiffness is badly conditioned */
  const double qmin = 0.05;
  int nfix = 0;
  for (int pass = 0; pass < 5; pass++) {
    int changed = 0;
    for (int t = 0; t < m->ntet; t++) {
      if (tetQuality(m, t) >= qmin) {
        continue;
      }
      int* tv = m->tet + 10 * t;
      for (int a = 0; a < 4; a++) {
        for (int b = a + 1; b < 4; b++) {
          int en = tv[edgeNode(a, b)];
          for (int d = 0; d < 3; d++) {
            m->x[3 * en + d] = 0.5 * (m->x[3 * tv[a] + d] + m->x[3 * tv[b] + d]);
          }
        }
      }
      changed++;
    }
    nfix += changed;
    if (!changed) {
      break;
    }
  }
  return nfix;
}
