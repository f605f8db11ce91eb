/* fem_output.c: VTU writer and ABAQUS/CalculiX deck export (see fem_output.h). */
#include "fem_output.h"

#include <errno.h>
#include <string.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core_text.h"

#define VTK_QUADRATIC_TETRA 24


csStatus csf_writeVtu(const csfModel* m, const csfData* d, const char* path, csError* err) {
  FILE* f = fopen(path, "w");
  if (!f) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot write VTU file: %s", path, strerror(errno));
  }
  const csfMesh* me = m->mesh;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n");
  fprintf(f, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n", me->nnode, me->ntet);
  fprintf(f, "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (int i = 0; i < me->nnode; i++) {
    fprintf(f, "%.9g %.9g %.9g\n", me->x[3 * i] + d->u[3 * i], me->x[3 * i + 1] + d->u[3 * i + 1],
            me->x[3 * i + 2] + d->u[3 * i + 2]);
  }
  fprintf(f, "</DataArray></Points>\n<Cells>\n");
  fprintf(f, "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
  for (int e = 0; e < me->ntet; e++) {
    for (int a = 0; a < 10; a++) {
      fprintf(f, "%d%c", me->tet[10 * e + a], a == 9 ? '\n' : ' ');
    }
  }
  fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
  for (int e = 0; e < me->ntet; e++) {
    fprintf(f, "%d\n", 10 * (e + 1));
  }
  fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (int e = 0; e < me->ntet; e++) {
    fprintf(f, "%d\n", VTK_QUADRATIC_TETRA);
  }
  fprintf(f, "</DataArray>\n</Cells>\n");
  fprintf(f, "<PointData Vectors=\"displacement\"><DataArray type=\"Float64\" "
             "Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (int i = 0; i < me->nnode; i++) {
    fprintf(f, "%.9g %.9g %.9g\n", d->u[3 * i], d->u[3 * i + 1], d->u[3 * i + 2]);
  }
  fprintf(f, "</DataArray></PointData>\n<CellData>\n");
  fprintf(f, "<DataArray type=\"Float64\" Name=\"cauchy_stress\" NumberOfComponents=\"6\" "
             "format=\"ascii\">\n");
  double* vm = malloc((size_t)me->ntet * sizeof(double));
  for (int e = 0; e < me->ntet; e++) {
    double s[6];
    csf_tetCauchyAt(m, d, e, s);
    fprintf(f, "%.6g %.6g %.6g %.6g %.6g %.6g\n", s[0], s[1], s[2], s[3], s[4], s[5]);
    if (vm) {
      vm[e] = sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                          (s[2] - s[0]) * (s[2] - s[0])) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
    }
  }
  fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n");
  for (int e = 0; e < me->ntet; e++) {
    fprintf(f, "%.6g\n", vm ? vm[e] : 0.0);
  }
  free(vm);
  fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"theta\" format=\"ascii\">\n");
  for (int e = 0; e < me->ntet; e++) {
    fprintf(f, "%.9g\n", d->vratio[e]);
  }
  fprintf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  return csu_writeClose(f, path, "the deformed mesh (VTU)", err);
}


/* ABAQUS face number (1..4) of a tetrahedron face given by its local corner ids */
static int abaqusFace(const int* tv, const int* fv) {
  int has[4] = {0, 0, 0, 0};
  for (int k = 0; k < 3; k++) {
    for (int a = 0; a < 4; a++) {
      has[a] |= tv[a] == fv[k];
    }
  }
  if (!has[3]) {
    return 1; /* (1,2,3) */
  }
  if (!has[2]) {
    return 2; /* (1,4,2) */
  }
  if (!has[0]) {
    return 3; /* (2,4,3) */
  }
  return 4; /* (3,4,1) */
}


csStatus csf_writeInp(const csfModel* m, const csrActuator* act, double pressure,
                      const char* path, csError* err) {
  FILE* f = fopen(path, "w");
  if (!f) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot write input deck: %s", path, strerror(errno));
  }
  const csfMesh* me = m->mesh;
  fprintf(f, "*HEADING\ncrawlsim 3D-FRSPA actuator '%s' (units mm, N, MPa, t/mm^3, s)\n",
          act->name);
  fprintf(f, "** CalculiX: replace TYPE=C3D10H by TYPE=C3D10 (no hybrid elements in CalculiX)\n");
  fprintf(f, "*NODE, NSET=NBODY\n");
  for (int i = 0; i < me->nnode; i++) {
    fprintf(f, "%d, %.12g, %.12g, %.12g\n", i + 1, me->x[3 * i], me->x[3 * i + 1],
            me->x[3 * i + 2]);
  }
  /* C3D10 node order equals VTK's: corners, (1,2) (2,3) (3,1) (1,4) (2,4) (3,4) */
  fprintf(f, "*ELEMENT, TYPE=C3D10H, ELSET=BODY\n");
  for (int e = 0; e < me->ntet; e++) {
    const int* t = me->tet + 10 * e;
    fprintf(f, "%d, %d, %d, %d, %d, %d, %d, %d, %d, %d,\n%d\n", e + 1, t[0] + 1, t[1] + 1,
            t[2] + 1, t[3] + 1, t[4] + 1, t[5] + 1, t[6] + 1, t[7] + 1, t[8] + 1, t[9] + 1);
  }
  fprintf(f, "*NSET, NSET=BASE\n");
  int col = 0;
  for (int i = 0; i < me->nnode; i++) {
    if (m->fixed[3 * i] && m->fixed[3 * i + 1] && m->fixed[3 * i + 2]) {
      fprintf(f, "%d,%s", i + 1, (++col % 12 == 0) ? "\n" : " ");
    }
  }
  fprintf(f, "\n");
  /* fibres: two nodes per truss, embedded in the body */
  int nb = me->nnode, eb = me->ntet;
  if (m->nfib > 0) {
    fprintf(f, "*NODE, NSET=NFIBRE\n");
    for (int k = 0; k < m->nfib; k++) {
      for (int end = 0; end < 2; end++) {
        double X[3] = {0, 0, 0};
        for (int a = 0; a < 10; a++) {
          int q = 20 * k + 10 * end + a;
          double c = fabs(m->fib_coef[q]);
          for (int d = 0; d < 3; d++) {
            X[d] += c * me->x[3 * m->fib_node[q] + d];
          }
        }
        fprintf(f, "%d, %.12g, %.12g, %.12g\n", nb + 2 * k + end + 1, X[0], X[1], X[2]);
      }
    }
    fprintf(f, "*ELEMENT, TYPE=T3D2, ELSET=FIBRE\n");
    for (int k = 0; k < m->nfib; k++) {
      fprintf(f, "%d, %d, %d\n", eb + k + 1, nb + 2 * k + 1, nb + 2 * k + 2);
    }
    fprintf(f, "*EMBEDDED ELEMENT, HOST ELSET=BODY\nFIBRE\n");
    fprintf(f, "*SOLID SECTION, ELSET=FIBRE, MATERIAL=KEVLAR\n%.9g\n", CS_PI * act->rf * act->rf);
    fprintf(f, "*MATERIAL, NAME=KEVLAR\n*ELASTIC\n%.9g, %.9g\n*DENSITY\n%.9g\n", act->Ef,
            act->nuf, act->rhof);
  }
  fprintf(f, "*MATERIAL, NAME=ELASTOSIL\n*HYPERELASTIC, YEOH\n%.9g, %.9g, 0., %.9g, 0., 0.\n",
          m->mat.C10, m->mat.C20, 2.0 / m->mat.kappa);
  fprintf(f, "*DENSITY\n%.9g\n*SOLID SECTION, ELSET=BODY, MATERIAL=ELASTOSIL\n", m->mat.rho);
  /* one surface per loaded chamber tag */
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 1; j <= 4; j++) {
      int tag = CSF_TAG_CHAMBER(s, j), any = 0;
      for (int q = 0; q < me->nface; q++) {
        any |= me->face_tag[q] == tag && m->face_p[q] != 0;
      }
      if (!any) {
        continue;
      }
      fprintf(f, "*SURFACE, NAME=CH%d_%d, TYPE=ELEMENT\n", s + 1, j);
      for (int q = 0; q < me->nface; q++) {
        if (me->face_tag[q] == tag) {
          int t = me->face_tet[q];
          fprintf(f, "%d, S%d\n", t + 1, abaqusFace(me->tet + 10 * t, me->face + 6 * q));
        }
      }
    }
  }
  fprintf(f, "*BOUNDARY\nBASE, 1, 3\n");
  fprintf(f, "*STEP, NLGEOM, INC=1000\n*STATIC\n0.01, 1.0, 1e-6, 0.05\n*DSLOAD\n");
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 1; j <= 4; j++) {
      int tag = CSF_TAG_CHAMBER(s, j), any = 0;
      for (int q = 0; q < me->nface; q++) {
        any |= me->face_tag[q] == tag && m->face_p[q] != 0;
      }
      if (any) {
        fprintf(f, "CH%d_%d, P, %.9g\n", s + 1, j, pressure);
      }
    }
  }
  fprintf(f, "*NODE FILE\nU\n*EL FILE\nS\n*END STEP\n");
  return csu_writeClose(f, path, "the solver deck (.inp)", err);
}
