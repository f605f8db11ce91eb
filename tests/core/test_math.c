/* test_math.c: the small math of core_math.h that the coupling and the ODE helpers rely on:
 * the spring -> ERP/CFM map (against the implicit-Euler spring-damper it stands for), the
 * rotation-vector <-> matrix pair, and the symmetric 3x3 eigen solver. */
#include <math.h>
#include <stdio.h>

#include "core_math.h"
#include "cs_test.h"


/* ODE's soft row with ERP/CFM at step h, on a unit mass with position error x and velocity v,
 * gives the force f = (ERP x / h + ... ) solved from J v' = -ERP x / h - CFM f (ODE manual); for
 * the map to be the implicit spring-damper, f must equal -kp (x + h v') - kd v' for the same v'.
 * Solve both for one step of a mass m and compare the new velocities. */
static void test_erp_cfm_is_the_implicit_spring(void) {
  double h = 1e-3, m = 2e-5, x = 0.3, v = -4.0;
  double cases[3][2] = {{100.0, 0.1}, {5.0, 0.0}, {0.0, 0.02}}; /* kp, kd */
  for (int c = 0; c < 3; c++) {
    double kp = cases[c][0], kd = cases[c][1], erp = NAN, cfm = NAN;
    CS_EXPECT(csu_springErpCfm(h, kp, kd, &erp, &cfm) == 0);
    /* ODE: v' = v + h f / m with v' = -(ERP/h) x - CFM f  ->  f = (-(ERP/h) x - v) / (CFM + h/m) */
    double f_ode = (-(erp / h) * x - v) / (cfm + h / m);
    /* implicit Euler: f = -kp (x + h v') - kd v', v' = v + h f / m */
    double f_imp = (-kp * x - (kp * h + kd) * v) / (1 + (kp * h + kd) * h / m);
    /* the two are algebraically equal; 1e-12 relative is a few ulps of the terms summed */
    CS_EXPECT_NEAR(f_ode, f_imp, 1e-15, 1e-12);
  }
  double e = -1, f = -1;
  CS_EXPECT(csu_springErpCfm(0, 1, 1, &e, &f) == -1);
  CS_EXPECT(csu_springErpCfm(1e-3, -1, 1, &e, &f) == -1);
  CS_EXPECT(csu_springErpCfm(1e-3, 1, -1, &e, &f) == -1);
  CS_EXPECT(csu_springErpCfm(1e-3, 0, 0, &e, &f) == -1);
  CS_EXPECT(csu_springErpCfm(1e-3, NAN, 1, &e, &f) == -1);
  CS_EXPECT(csu_springErpCfm(1e-3, INFINITY, 1, &e, &f) == -1);
  CS_EXPECT(e == -1 && f == -1); /* untouched on failure */
  /* pure spring and pure damper */
  CS_EXPECT(csu_springErpCfm(1e-3, 5, 0, &e, &f) == 0 && e == 1.0);
  CS_EXPECT(csu_springErpCfm(1e-3, 0, 5, &e, &f) == 0 && e == 0.0 && f == 0.2);
}


static void test_rotation_vector_round_trip(void) {
  /* small, moderate and near-pi angles about skew axes */
  double angles[5] = {0.0, 1e-9, 0.3, 2.9, 3.14159};
  for (int a = 0; a < 5; a++) {
    double u[3] = {0.3, -0.5, 0.8};
    csu_normalize3(u);
    double phi[3], R[9], back[3];
    csu_scale3(phi, u, angles[a]);
    csu_rotVecToMat3(R, phi);
    /* R is a rotation: R^T R = I to round-off */
    double RT[9], I[9];
    csu_transpose3(RT, R);
    csu_mulMat3(I, RT, R);
    for (int i = 0; i < 9; i++) {
      /* 4e-15: a few ulps of the nine-term products (measured 1.1e-15) */
      CS_EXPECT_NEAR(I[i], i % 4 == 0 ? 1.0 : 0.0, 4e-15, 0);
    }
    csu_mat3ToRotVec(back, R);
    /* 1e-14 rad: both branches are well conditioned (skew part below pi/2, symmetric part
     * above); the skew-only formula lost 1e-11 at 3.14159 (measured), which this bound catches */
    for (int i = 0; i < 3; i++) {
      CS_EXPECT_NEAR(back[i], phi[i], 1e-14, 0);
    }
  }
}


/* csu_mat3ToQuat inverts csu_quatToMat3 (up to the sign of q) in every branch of Shepperd's
 * method: small angles (trace largest), half turns about each axis (one diagonal entry largest) */
static void test_quat_of_matrix_round_trip(void) {
  const double axes[5][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, 3}, {-2, 0.5, 1}};
  const double angles[4] = {1e-9, 0.7, 3.0, 3.14159265358979};
  for (int a = 0; a < 5; a++) {
    for (int k = 0; k < 4; k++) {
      double u[3] = {axes[a][0], axes[a][1], axes[a][2]};
      csu_normalize3(u);
      const double h = 0.5 * angles[k];
      const double q[4] = {cos(h), sin(h) * u[0], sin(h) * u[1], sin(h) * u[2]};
      double R[9], p[4];
      csu_quatToMat3(R, q);
      csu_mat3ToQuat(p, R);
      const double sgn = p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3] < 0 ? -1 : 1;
      for (int j = 0; j < 4; j++) {
        CS_EXPECT_NEAR(sgn * p[j], q[j], 1e-14, 0);
      }
    }
  }
}


static void test_sym_eigen3(void) {
  /* A = V diag(w) V^T for a random-looking symmetric matrix and for repeated eigenvalues */
  double mats[3][9] = {{4, 1, -2, 1, 3, 0.5, -2, 0.5, 1},
                       {2, 0, 0, 0, 2, 0, 0, 0, 5},
                       {1e-3, 2e-4, 0, 2e-4, 1e-3, 0, 0, 0, 0}};
  for (int c = 0; c < 3; c++) {
    const double* A = mats[c];
    double w[3], V[9];
    csu_symEigen3(A, w, V);
    double scale = 0;
    for (int i = 0; i < 9; i++) {
      scale = fmax(scale, fabs(A[i]));
    }
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        double a = 0, vv = 0;
        for (int k = 0; k < 3; k++) {
          a += V[3 * i + k] * w[k] * V[3 * j + k];
          vv += V[3 * k + i] * V[3 * k + j];
        }
        /* reconstruction and orthonormality to a few ulps of the matrix's scale */
        CS_EXPECT_NEAR(a, A[3 * i + j], 1e-14 * scale, 0);
        CS_EXPECT_NEAR(vv, i == j ? 1.0 : 0.0, 1e-14, 0);
      }
    }
  }
  /* the trace and determinant of case 0 are the eigenvalues' sum and product */
  double w[3], V[9];
  csu_symEigen3(mats[0], w, V);
  CS_EXPECT_NEAR(w[0] + w[1] + w[2], 8.0, 1e-13, 0);
}


/* the n x n case at n = 6 (the coupling's passive projection): A = V diag(w) V^T and V
 * orthonormal for a matrix with mixed scales (translation ~1e-4, rotation ~1, as the support's
 * inertia metric mixes them), one negative eigenvalue, and the known spectrum of a matrix built
 * from a chosen one: Q diag(d) Q^T with Q a product of plane rotations */
static void test_sym_eigen6(void) {
  const double d[6] = {-0.42, 3.7e-2, 4.1e-2, 75.0, 323.0, 742.0};
  double Q[36], A[36];
  for (int i = 0; i < 36; i++) {
    Q[i] = i % 7 == 0 ? 1.0 : 0.0;
  }
  /* Q = product of rotations in planes (p, q) by angles 0.3 (p + 1) + 0.1 q */
  for (int p = 0; p < 5; p++) {
    for (int q = p + 1; q < 6; q++) {
      const double th = 0.3 * (p + 1) + 0.1 * q, c = cos(th), sn = sin(th);
      for (int k = 0; k < 6; k++) {
        const double a = Q[6 * k + p], b = Q[6 * k + q];
        Q[6 * k + p] = c * a - sn * b;
        Q[6 * k + q] = sn * a + c * b;
      }
    }
  }
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += Q[6 * i + k] * d[k] * Q[6 * j + k];
      }
      A[6 * i + j] = s;
    }
  }
  double w[6], V[36];
  csu_symEigenN(6, A, w, V);
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double a = 0, vv = 0;
      for (int k = 0; k < 6; k++) {
        a += V[6 * i + k] * w[k] * V[6 * j + k];
        vv += V[6 * k + i] * V[6 * k + j];
      }
      /* round-off of a few sweeps of 15 rotations: 1e-13 of the largest eigenvalue */
      CS_EXPECT_NEAR(a, A[6 * i + j], 1e-13 * 742.0, 0);
      CS_EXPECT_NEAR(vv, i == j ? 1.0 : 0.0, 1e-13, 0);
    }
  }
  /* the spectrum: each chosen eigenvalue found (unsorted) to 1e-12 of the largest */
  for (int k = 0; k < 6; k++) {
    double best = INFINITY;
    for (int i = 0; i < 6; i++) {
      best = fmin(best, fabs(w[i] - d[k]));
    }
    CS_EXPECT(best < 1e-12 * 742.0);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_erp_cfm_is_the_implicit_spring);
  CS_RUN(test_rotation_vector_round_trip);
  CS_RUN(test_quat_of_matrix_round_trip);
  CS_RUN(test_sym_eigen3);
  CS_RUN(test_sym_eigen6);
  return cs_testSummary();
}
