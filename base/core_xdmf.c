/* core_xdmf.c: the XDMF companion of a run file (see core_xdmf.h).
 *
 * XDMF 3 (xdmf.org, "XDMF Model and Format"): Light data in XML, heavy data in HDF5 referenced
 * as "file.h5:/path"; a HyperSlab DataItem selects one sample of a series by its start, stride
 * and count rows; Hexahedron corners in VTK order, Polyline with NodesPerElement. Written by
 * hand with fprintf: the structure is fixed and small. */
#include "core_xdmf.h"

#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the series a run file has (sim_run.c) */
static const char kLegs[] = "ABCDEFGH";


long cs_xdmfStride(long n, long max_frames) {
  if (n <= 0 || max_frames <= 0) {
    return 1;
  }
  long s = (n + max_frames - 1) / max_frames;
  return s < 1 ? 1 : s;
}


/* dims of a dataset (rank <= 3), 0 if absent */
static int datasetDims(hid_t f, const char* path, hsize_t dims[3]) {
  dims[0] = dims[1] = dims[2] = 0;
  if (H5Lexists(f, path, H5P_DEFAULT) <= 0) {
    return 0;
  }
  hid_t ds = H5Dopen2(f, path, H5P_DEFAULT);
  if (ds < 0) {
    return 0;
  }
  hid_t sp = H5Dget_space(ds);
  int rank = H5Sget_simple_extent_ndims(sp);
  if (rank >= 1 && rank <= 3) {
    H5Sget_simple_extent_dims(sp, dims, NULL);
  } else {
    rank = 0;
  }
  H5Sclose(sp);
  H5Dclose(ds);
  return rank;
}


/* the values of /time (n doubles) into t */
static int readTime(hid_t f, double* t, hsize_t n) {
  hid_t ds = H5Dopen2(f, "/time", H5P_DEFAULT);
  if (ds < 0) {
    return -1;
  }
  (void)n;
  herr_t rc = H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t);
  H5Dclose(ds);
  return rc < 0 ? -1 : 0;
}


/* a hyperslab of sample i of an [N, a, 3] series as an (a x 3) geometry */
static void slab(FILE* x, const char* h5, const char* path, long i, hsize_t N, hsize_t a) {
  fprintf(x, "<Geometry GeometryType=\"XYZ\"><DataItem ItemType=\"HyperSlab\" "
             "Dimensions=\"%llu 3\" Type=\"HyperSlab\">"
             "<DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 0 1 1 1 1 %llu 3</DataItem>"
             "<DataItem Dimensions=\"%llu %llu 3\" NumberType=\"Float\" Precision=\"8\" "
             "Format=\"HDF\">%s:%s</DataItem></DataItem></Geometry>\n",
          (unsigned long long)a, i, (unsigned long long)a, (unsigned long long)N,
          (unsigned long long)a, h5, path);
}


/* an attribute of one cell from sample i of an [N, C] series: columns c0 .. c0 + n - 1 (a
 * Scalar, Vector or Matrix of n components per the XDMF 3 model) */
static void attrSlab(FILE* x, const char* h5, const char* name, const char* type,
                     const char* path, long i, hsize_t N, hsize_t C, hsize_t c0, hsize_t n) {
  fprintf(x, "<Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Cell\"><DataItem "
             "ItemType=\"HyperSlab\" Dimensions=\"1 %llu\" Type=\"HyperSlab\">"
             "<DataItem Dimensions=\"3 2\" Format=\"XML\">%ld %llu 1 1 1 %llu</DataItem>"
             "<DataItem Dimensions=\"%llu %llu\" NumberType=\"Float\" Precision=\"8\" "
             "Format=\"HDF\">%s:%s</DataItem></DataItem></Attribute>\n",
          name, type, (unsigned long long)n, i, (unsigned long long)c0, (unsigned long long)n,
          (unsigned long long)N, (unsigned long long)C, h5, path);
}


/* an attribute of one cell from sample i, leg k of an [N, 8, 3] series (a Vector) */
static void legVectorSlab(FILE* x, const char* h5, const char* name, const char* path, long i,
                          int k, hsize_t N) {
  fprintf(x, "<Attribute Name=\"%s\" AttributeType=\"Vector\" Center=\"Cell\"><DataItem "
             "ItemType=\"HyperSlab\" Dimensions=\"1 3\" Type=\"HyperSlab\">"
             "<DataItem Dimensions=\"3 3\" Format=\"XML\">%ld %d 0 1 1 1 1 1 3</DataItem>"
             "<DataItem Dimensions=\"%llu 8 3\" NumberType=\"Float\" Precision=\"8\" "
             "Format=\"HDF\">%s:%s</DataItem></DataItem></Attribute>\n",
          name, i, k, (unsigned long long)N, h5, path);
}


csStatus cs_xdmfWriteRun(const char* h5_path, const char* xdmf_path, long stride, csError* err) {
  if (stride < 1) {
    stride = 1;
  }
  const char* base = strrchr(h5_path, '/');
  base = base ? base + 1 : h5_path;
  hid_t f = H5Fopen(h5_path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open the run file for its XDMF", h5_path);
  }
  hsize_t dt[3], dc[3], dl[3], dterr[3];
  int ok = datasetDims(f, "/time", dt) == 1 && datasetDims(f, "/support/corners", dc) == 3 &&
           datasetDims(f, "/legs/A/centerline", dl) == 3;
  int have_terrain = datasetDims(f, "/terrain/corners", dterr) == 2 && dterr[0] % 8 == 0;
  /* the attributes (optional: a file without them still shows its shapes) */
  hsize_t dp[3], dfc[3];
  int have_p = datasetDims(f, "/pressure", dp) == 2 && dp[1] == 96;
  int have_f = datasetDims(f, "/contact/force", dfc) == 2 && dfc[1] == 3;
  hsize_t dff[3], dst[3];
  int have_ff = datasetDims(f, "/contact/foot_force", dff) == 3 && dff[1] == 8 && dff[2] == 3;
  int have_st = datasetDims(f, "/contact/stance", dst) == 2 && dst[1] == 8;
  hsize_t N = dt[0], nleg[8];
  /* a run that stopped between appends may have series one sample apart: frames go to the
   * shortest; each hyperslab names its own dataset's full shape */
  if (ok) {
    N = dc[0] < N ? dc[0] : N;
    for (int k = 0; k < 8; k++) {
      char p[64];
      hsize_t d[3];
      snprintf(p, sizeof p, "/legs/%c/centerline", kLegs[k]);
      ok = ok && datasetDims(f, p, d) == 3 && d[1] == dl[1] && d[2] == 3;
      nleg[k] = d[0];
      N = (ok && d[0] < N) ? d[0] : N;
    }
  }
  if (!ok) {
    H5Fclose(f);
    return cs_errorSet(err, CS_ERR_IO, "%s: not a crawlsim run file (no /time, /support/corners "
                       "or /legs/*/centerline)", h5_path);
  }
  double* t = N > 0 ? malloc((size_t)dt[0] * sizeof(double)) : NULL;
  if (N > 0 && !t) {
    H5Fclose(f);
    return cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory for the times of %s", xdmf_path,
                       h5_path);
  }
  if (N > 0 && readTime(f, t, dt[0]) != 0) {
    free(t);
    H5Fclose(f);
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot read /time", h5_path);
  }
  H5Fclose(f);
  /* written beside as "<xdmf>.part" and renamed into place: never a half file under its name */
  char part[1100];
  if (snprintf(part, sizeof part, "%s.part", xdmf_path) >= (int)sizeof part) {
    free(t);
    return cs_errorSet(err, CS_ERR_ARG, "%s: path too long", xdmf_path);
  }
  FILE* x = fopen(part, "w");
  if (!x) {
    free(t);
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot create (%s)", xdmf_path, strerror(errno));
  }
  hsize_t K = dl[1];
  fprintf(x, "<?xml version=\"1.0\" ?>\n<!-- crawlsim run: %s (support, legs A..H over time; "
             "mm, s) -->\n<Xdmf Version=\"3.0\">\n<Domain>\n", base);
  if (have_terrain && dterr[0] > 0) {
    hsize_t nb = dterr[0] / 8;
    fprintf(x, "<Grid Name=\"terrain\" GridType=\"Uniform\">\n"
               "<Topology TopologyType=\"Hexahedron\" NumberOfElements=\"%llu\">"
               "<DataItem Dimensions=\"%llu 8\" NumberType=\"Int\" Format=\"XML\">",
            (unsigned long long)nb, (unsigned long long)nb);
    for (hsize_t i = 0; i < nb * 8; i++) {
      fprintf(x, "%s%llu", i ? " " : "", (unsigned long long)i);
    }
    fprintf(x, "</DataItem></Topology>\n<Geometry GeometryType=\"XYZ\"><DataItem "
               "Dimensions=\"%llu 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:"
               "/terrain/corners</DataItem></Geometry>\n</Grid>\n",
            (unsigned long long)(nb * 8), base);
  }
  fprintf(x, "<Grid Name=\"robot\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (hsize_t i = 0; i < N; i += (hsize_t)stride) {
    fprintf(x, "<Grid Name=\"frame %llu\" GridType=\"Collection\" CollectionType=\"Spatial\">"
               "<Time Value=\"%.9g\"/>\n", (unsigned long long)i, t[i]);
    fprintf(x, "<Grid Name=\"support\" GridType=\"Uniform\"><Topology TopologyType=\"Hexahedron\" "
               "NumberOfElements=\"1\"><DataItem Dimensions=\"1 8\" NumberType=\"Int\" "
               "Format=\"XML\">0 1 2 3 4 5 6 7</DataItem></Topology>\n");
    slab(x, base, "/support/corners", (long)i, dc[0], 8);
    if (have_f && i < dfc[0]) {
      attrSlab(x, base, "contact_force_N", "Vector", "/contact/force", (long)i, dfc[0], 3, 0, 3);
    }
    fprintf(x, "</Grid>\n");
    for (int k = 0; k < 8; k++) {
      char p[64];
      snprintf(p, sizeof p, "/legs/%c/centerline", kLegs[k]);
      fprintf(x, "<Grid Name=\"leg_%c\" GridType=\"Uniform\"><Topology TopologyType=\"Polyline\" "
                 "NumberOfElements=\"1\" NodesPerElement=\"%llu\"><DataItem Dimensions=\"1 %llu\" "
                 "NumberType=\"Int\" Format=\"XML\">",
              kLegs[k], (unsigned long long)K, (unsigned long long)K);
      for (hsize_t j = 0; j < K; j++) {
        fprintf(x, "%s%llu", j ? " " : "", (unsigned long long)j);
      }
      fprintf(x, "</DataItem></Topology>\n");
      slab(x, base, p, (long)i, nleg[k], K);
      if (have_p && i < dp[0]) { /* the leg's 12 chambers: labels 12 k + 1 .. 12 k + 12 */
        attrSlab(x, base, "pressure_MPa", "Matrix", "/pressure", (long)i, dp[0], 96,
                 (hsize_t)(12 * k), 12);
      }
      if (have_ff && i < dff[0]) {
        legVectorSlab(x, base, "foot_force_N", "/contact/foot_force", (long)i, k, dff[0]);
      }
      if (have_st && i < dst[0]) {
        attrSlab(x, base, "stance", "Scalar", "/contact/stance", (long)i, dst[0], 8,
                 (hsize_t)k, 1);
      }
      fprintf(x, "</Grid>\n");
    }
    fprintf(x, "</Grid>\n");
  }
  fprintf(x, "</Grid>\n</Domain>\n</Xdmf>\n");
  free(t);
  int bad = ferror(x) || fflush(x) != 0;
  int e = errno;
  if (fclose(x) != 0 && !bad) {
    bad = 1, e = errno;
  }
  if (!bad && rename(part, xdmf_path) != 0) {
    bad = 1, e = errno;
  }
  if (bad) {
    remove(part);
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot write (%s)", xdmf_path, strerror(e));
  }
  return CS_OK;
}
