/* fem_bend_branch.c: chamber volumes, twin-chamber asymmetry and the bifurcation report of the
 * sweep (see fem_bend_branch.h).
 *
 * Rationale. The branch switch itself lives in the path layer (fem_path.c); what a user needs
 * from the sweep is what broke: the critical mode's largest component located in the section
 * (the 1 mm webs of the thin-walled Sec. 4 actuator are the candidates, README "Design
 * studies"), and a measure of the new branch that does not depend on the mode's scaling: the
 * volumes of the twin chambers Omega1 / Omega2, equal on the symmetric path. */
#include "fem_bend_branch.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fem_mesh.h"

/* signed volume of the tetrahedron (origin, a, b, c) times 6 */
static double tripleProduct(const double* a, const double* b, const double* c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}


double csf_chamberVolume(const csfModel* m, const csfData* d, int tag) {
  const csfMesh* me = m->mesh;
  /* Tri6 in VTK order: corners 0 1 2, edge nodes 3 (0-1), 4 (1-2), 5 (2-0) */
  static const int sub[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  double v6 = 0;
  for (int f = 0; f < me->nface; f++) {
    if (me->face_tag[f] != tag) {
      continue;
    }
    const int* fn = me->face + 6 * (size_t)f;
    double x[6][3];
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        x[a][i] = me->x[3 * fn[a] + i] + d->u[3 * fn[a] + i];
      }
    }
    for (int t = 0; t < 4; t++) {
      v6 += tripleProduct(x[sub[t][0]], x[sub[t][1]], x[sub[t][2]]);
    }
  }
  return -v6 / 6.0; /* the faces' normals point into the chamber */
}


double csf_bendChamberAsymmetry(const csfModel* m, const csfData* d,
                                const double ratio[CSR_NSEG][CSR_NCHAMBER],
                                double asym[CSR_NSEG]) {
  double worst = NAN;
  for (int s = 0; s < CSR_NSEG; s++) {
    asym[s] = NAN;
    int jj[CSR_NCHAMBER], np = 0;
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      if (ratio[s][j] != 0.0) {
        jj[np++] = j;
      }
    }
    if (np != 2 || ratio[s][jj[0]] != ratio[s][jj[1]]) {
      continue;
    }
    const double va = csf_chamberVolume(m, d, CSF_TAG_CHAMBER(s, jj[0] + 1));
    const double vb = csf_chamberVolume(m, d, CSF_TAG_CHAMBER(s, jj[1] + 1));
    asym[s] = (va - vb) / (va + vb);
    if (isnan(worst) || fabs(asym[s]) > worst) {
      worst = fabs(asym[s]);
    }
  }
  return worst;
}


void csf_bendDescribePoint(const csrActuator* act, const double X[3], char* out, size_t sz) {
  /* along the length: segments and joints in order from the base */
  const double z = X[2];
  char where[48];
  double z0 = 0;
  snprintf(where, sizeof where, "beyond the tip");
  for (int s = 0; s < CSR_NSEG; s++) {
    if (z <= z0 + act->S[s]) {
      snprintf(where, sizeof where, "segment II%d", s + 1);
      break;
    }
    z0 += act->S[s];
    if (s < CSR_NSEG - 1) {
      if (z <= z0 + act->LS[s]) {
        snprintf(where, sizeof where, "joint II%d-II%d", s + 1, s + 2);
        break;
      }
      z0 += act->LS[s];
    }
  }
  /* in the section: chamber j at (sx b, sy b), j = 1..4 (fem_mesh.c) */
  static const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, -1, 1};
  double dist[4];
  int j1 = 0, j2 = -1;
  for (int j = 0; j < 4; j++) {
    dist[j] = hypot(X[0] - sx[j] * act->b, X[1] - sy[j] * act->b) - act->r1;
    j1 = dist[j] < dist[j1] ? j : j1;
  }
  for (int j = 0; j < 4; j++) {
    if (j != j1 && (j2 < 0 || dist[j] < dist[j2])) {
      j2 = j;
    }
  }
  const double web = 2.0 * act->b - 2.0 * act->r1; /* between neighbouring chambers, mm */
  const double outer = act->a - act->b - act->r1;  /* chamber to the flat side, mm */
  char sect[96];
  if (dist[j1] + dist[j2] <= 1.5 * web) { /* near the line between two centres */
    snprintf(sect, sizeof sect, "in the %.2g mm wall between chambers %d and %d", web,
             (j1 < j2 ? j1 : j2) + 1, (j1 < j2 ? j2 : j1) + 1);
  } else if (fabs(X[0]) >= act->b + act->r1 || fabs(X[1]) >= act->b + act->r1) {
    snprintf(sect, sizeof sect, "in the %.2g mm outer wall of chamber %d", outer, j1 + 1);
  } else {
    snprintf(sect, sizeof sect, "%.2f mm from chamber %d's wall", dist[j1], j1 + 1);
  }
  snprintf(out, sz, "%s, %s (reference %.2f, %.2f, %.2f mm)", where, sect, X[0], X[1], X[2]);
}


void csf_bendBifurcationNote(const csrActuator* act, const csfLimitResult* res, double a_bif,
                             double amp, double asym_branch, char* out, size_t sz) {
  const csfCriticalMode* cm = &res->mode;
  char where[200] = "-";
  if (cm->node_max >= 0) {
    csf_bendDescribePoint(act, cm->X_max, where, sizeof where);
  }
  char branch[560];
  if (res->switched) {
    snprintf(branch, sizeof branch, "branch switched: perturbation %+.3g mm along the mode, "
             "the first branch state %.3g mm along it, %d negative pivots, twin-chamber "
             "asymmetry %.2e", res->branch_sign * amp, res->branch_xi, res->branch_neg,
             asym_branch);
  } else if (res->branch_tries == 0) {
    snprintf(branch, sizeof branch, "the path is kept (branch switching not tried: "
             "--branch-switch 1)");
  } else {
    snprintf(branch, sizeof branch, "no branch accepted after %d perturbed solves: %.480s",
             res->branch_tries, res->branch_note);
  }
  snprintf(out, sz, "bifurcation at %.5f MPa (%.2f deg; the tangent gained a negative pivot "
           "while the pressure rose; %d at the state): critical mode lambda %.3g N/mm (inverse "
           "iteration on K - sigma I, sigma %.3g after %d shifted factorisations; residual "
           "%.1e, %d solves), volume component cos %.2f, largest in %s; %s", res->p_bif, a_bif,
           cm->neg_pivots, cm->lambda, cm->sigma, cm->n_shift, cm->residual, cm->iters,
           cm->b_cos, where, branch);
}
